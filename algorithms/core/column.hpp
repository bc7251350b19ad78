// An append-only array for the recorder's hot path. push_back is a bound check, a store and an
// increment, always inlined; growth is out of line. (std::vector's push_back, with its growth
// path inline, stopped being inlined into the recording calls, and a call per item was most of
// the cost of a step.) T must be trivially copyable: memory is moved by realloc and never
// destroyed element by element.
#pragma once
#include <algorithm>
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>
#include <type_traits>
#include <vector>

namespace sw {

template <class T> class Column {
  static_assert(std::is_trivially_copyable_v<T>);

 public:
  Column() = default;
  Column(const Column& o) { *this = o; }
  Column(Column&& o) noexcept : data_(o.data_), size_(o.size_), cap_(o.cap_) { o.data_ = nullptr, o.size_ = o.cap_ = 0; }
  Column& operator=(const Column& o) {
    if (this != &o) {
      clear();
      reserve(o.size_);
      if (o.size_) std::memcpy(data_, o.data_, o.size_ * sizeof(T));
      size_ = o.size_;
    }
    return *this;
  }
  Column& operator=(Column&& o) noexcept {
    std::swap(data_, o.data_), std::swap(size_, o.size_), std::swap(cap_, o.cap_);
    return *this;
  }
  ~Column() { std::free(data_); }

  [[gnu::always_inline]] void push_back(const T& x) {
    if (size_ == cap_) [[unlikely]]
      grow(size_ + 1);
    data_[size_++] = x;
  }
  void reserve(std::size_t n) {
    if (n > cap_) grow(n);
  }
  void clear() { size_ = 0; }  // keeps the memory: re-recording costs no allocation

  std::size_t size() const { return size_; }
  bool empty() const { return size_ == 0; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T& back() { return data_[size_ - 1]; }
  const T& back() const { return data_[size_ - 1]; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }

 private:
  [[gnu::noinline]] void grow(std::size_t need) {
    const std::size_t cap = std::max({need, 2 * cap_, std::size_t{16}});
    void* p = std::realloc(data_, cap * sizeof(T));
    if (!p) throw std::bad_alloc();
    data_ = static_cast<T*>(p), cap_ = cap;
  }

  T* data_ = nullptr;
  std::size_t size_ = 0, cap_ = 0;
};

// The recorder's store for values of type T: a Column where T allows it (float, double, int64,
// intervals), a std::vector otherwise (GMP rationals own memory).
template <class T> using RecordStore = std::conditional_t<std::is_trivially_copyable_v<T>, Column<T>, std::vector<T>>;

}  // namespace sw
