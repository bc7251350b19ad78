// Output files and streams: --out written the way cp and tee treat their target, and the
// --max-output byte budget (docs/cli.md).
#pragma once
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <ostream>
#include <streambuf>
#include "input.hpp"

namespace sw {

// An output file (--out), the way cp and tee treat their target (docs/cli.md):
// - a new or regular file is written under a temporary name beside it and renamed into place by
//   commit(); if it is never committed (an error on the way) the temporary is removed, and so it
//   is on SIGINT or SIGTERM: no partial output file;
// - a symbolic link is followed: its final target is replaced that way, and the link stays;
// - a FIFO or a character device (/dev/stdout, /dev/null) is written through, in place;
// - a directory, a socket or a block device is refused (InputError).
class AtomicFile {
 public:
  explicit AtomicFile(std::filesystem::path target);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  std::ostream& stream() { return out_; }
  void commit();

 private:
  std::filesystem::path target_, temp_;  // temp_ empty: written through
  std::ofstream out_;
  bool committed_ = false;
};

// A stream that passes bytes on to `out` and throws InputError once more than `max` have passed
// (naming --max-output). The caller's AtomicFile then leaves no file behind.
class BudgetedStream : public std::ostream {
 public:
  BudgetedStream(std::ostream& out, std::uint64_t max);

 private:
  struct Buf : std::streambuf {
    std::ostream* out = nullptr;
    std::uint64_t max = 0, written = 0;
    int_type overflow(int_type c) override;
    std::streamsize xsputn(const char* s, std::streamsize n) override;
    void count(std::streamsize n);
  } buf_;
};

}  // namespace sw
