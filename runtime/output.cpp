// Output files (OutputFile), the byte budget (BudgetedStream) and standard output's health.
#include "output.hpp"
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <optional>
#include <random>
#include <vector>

namespace sw {

namespace {

namespace fs = std::filesystem;

// The temporaries being written, for the signal handler: fixed storage, no allocation there.
constexpr int kMaxTemps = 8;
char g_temps[kMaxTemps][4096];
volatile std::sig_atomic_t g_temp_used[kMaxTemps];

extern "C" void remove_temps_and_die(int sig) {
  for (int k = 0; k < kMaxTemps; ++k)
    if (g_temp_used[k]) ::unlink(g_temps[k]);
  std::signal(sig, SIG_DFL);
  std::raise(sig);
}

// The signals that end a process by default and can be caught; one the parent set to be ignored
// (nohup's SIGHUP, say) stays ignored.
void install_signal_handlers() {
  for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGPIPE, SIGXFSZ, SIGXCPU, SIGALRM, SIGUSR1, SIGUSR2, SIGVTALRM, SIGPROF}) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_DFL) std::signal(sig, remove_temps_and_die);
  }
}

void register_temp(const std::string& path) {
  static const bool installed = (install_signal_handlers(), true);
  (void)installed;
  if (path.size() >= sizeof g_temps[0]) return;
  for (int k = 0; k < kMaxTemps; ++k)
    if (!g_temp_used[k]) {
      std::memcpy(g_temps[k], path.c_str(), path.size() + 1);
      g_temp_used[k] = 1;
      return;
    }
}

void unregister_temp(const std::string& path) {
  for (int k = 0; k < kMaxTemps; ++k)
    if (g_temp_used[k] && path == g_temps[k]) g_temp_used[k] = 0;
}

std::string why(int err) { return std::strerror(err); }

// A stream buffer over a descriptor: every write is checked, and the first failure throws
// InputError naming the output (the stream lets it through: exceptions(badbit)).
class FdBuf : public std::streambuf {
 public:
  FdBuf() : buf_(1 << 16) { setp(buf_.data(), buf_.data() + buf_.size()); }
  void attach(int fd, std::string shown) { fd_ = fd, shown_ = std::move(shown); }
  void flush_all() {
    write_out(pbase(), pptr() - pbase());
    setp(buf_.data(), buf_.data() + buf_.size());
  }

 protected:
  int_type overflow(int_type c) override {
    flush_all();
    if (c != traits_type::eof()) *pptr() = char(c), pbump(1);
    return traits_type::not_eof(c);
  }
  int sync() override {
    flush_all();
    return 0;
  }
  std::streamsize xsputn(const char* s, std::streamsize n) override {
    if (n <= epptr() - pptr()) {
      std::memcpy(pptr(), s, std::size_t(n));
      pbump(int(n));
      return n;
    }
    flush_all();
    write_out(s, n);
    return n;
  }

 private:
  void write_out(const char* s, std::streamsize n) {
    while (n > 0) {
      const ssize_t w = ::write(fd_, s, std::size_t(n));
      if (w < 0 && errno == EINTR) continue;
      if (w <= 0) throw InputError("cannot write " + shown_ + ": " + why(w < 0 ? errno : ENOSPC));
      s += w, n -= w;
    }
  }
  std::vector<char> buf_;
  int fd_ = -1;
  std::string shown_;
};

// The descriptor a path names, if it is one of /dev/stdin, /dev/stdout, /dev/stderr, /dev/fd/N
// or /proc/self/fd/N.
std::optional<int> descriptor_of(const fs::path& p) {
  const std::string s = p.lexically_normal().string();
  if (s == "/dev/stdin") return 0;
  if (s == "/dev/stdout") return 1;
  if (s == "/dev/stderr") return 2;
  for (std::string_view prefix : {"/dev/fd/", "/proc/self/fd/"}) {
    if (s.rfind(prefix, 0) != 0) continue;
    const std::string n = s.substr(prefix.size());
    if (n.empty() || n.size() > 9 || n.find_first_not_of("0123456789") != std::string::npos) return std::nullopt;
    return std::stoi(n);
  }
  return std::nullopt;
}

// A file created exclusively under a fresh name; -1 with errno if the directory refuses it.
int create_temp(const fs::path& near, fs::path& name) {
  std::random_device rd;
  for (int tries = 0; tries < 16; ++tries) {
    name = near;
    name += ".tmp-" + std::to_string(rd());
    const int fd = ::open(name.c_str(), O_RDWR | O_CREAT | O_EXCL | O_CLOEXEC, 0666);  // the umask applies; read back when rewritten in place
    if (fd >= 0 || errno != EEXIST) return fd;
  }
  return -1;
}

}  // namespace

struct OutputFile::Impl {
  enum class Mode : std::uint8_t { through, rename, in_place };
  Mode mode = Mode::through;
  fs::path target, temp;  // temp: the named temporary, if any
  std::string shown;      // the path as given, for messages
  int fd = -1;
  FdBuf buf;
  std::ostream os{&buf};
  bool committed = false;

  void drop_temp() {
    if (temp.empty()) return;
    ::unlink(temp.c_str());
    unregister_temp(temp.string());
    temp.clear();
  }
  // Copies the finished temporary into the target in place (its inode, mode, owner and links stay).
  void rewrite_in_place() {
    const int out = ::open(target.c_str(), O_WRONLY | O_TRUNC | O_CLOEXEC);
    if (out < 0) throw InputError("cannot write " + shown + ": " + why(errno));
    FdBuf copy;
    copy.attach(out, shown);
    char block[1 << 16];
    if (::lseek(fd, 0, SEEK_SET) != 0) throw InputError("cannot write " + shown + ": " + why(errno));
    for (;;) {
      const ssize_t r = ::read(fd, block, sizeof block);
      if (r < 0 && errno == EINTR) continue;
      if (r < 0) throw InputError("cannot write " + shown + ": " + why(errno));
      if (r == 0) break;
      copy.sputn(block, r);
    }
    copy.flush_all();
    if (::close(out) != 0) throw InputError("cannot write " + shown + ": " + why(errno));
  }
};

OutputFile::OutputFile(fs::path target) : impl_(std::make_unique<Impl>()) {
  Impl& m = *impl_;
  m.shown = target.string();
  m.os.exceptions(std::ios::badbit);  // the buffer's InputError passes through
  // Follow links (each relative to its own directory), bounded, stopping at a descriptor's name.
  fs::path p = std::move(target);
  for (int hops = 0;; ++hops) {
    if (const auto fd = descriptor_of(p)) {
      if (::fcntl(*fd, F_GETFD) < 0) throw InputError("--out " + m.shown + ": descriptor " + std::to_string(*fd) + " is not open");
      m.fd = ::fcntl(*fd, F_DUPFD_CLOEXEC, 3);
      if (m.fd < 0) throw InputError("cannot write " + m.shown + ": " + why(errno));
      m.buf.attach(m.fd, m.shown);
      return;
    }
    std::error_code ec;
    if (!fs::is_symlink(fs::symlink_status(p, ec))) break;
    if (hops == 40) throw InputError("--out " + m.shown + ": too many levels of symbolic links");
    const fs::path to = fs::read_symlink(p, ec);
    if (ec) throw InputError("cannot read the link " + p.string());
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  m.target = p;
  struct stat st {};
  const bool exists = ::stat(p.c_str(), &st) == 0;
  if (!exists && errno != ENOENT) throw InputError("cannot write " + m.shown + ": " + why(errno));
  if (exists && (S_ISFIFO(st.st_mode) || S_ISCHR(st.st_mode))) {  // written through, in place
    m.fd = ::open(p.c_str(), O_WRONLY | O_CLOEXEC);
    if (m.fd < 0) throw InputError("cannot write " + m.shown + ": " + why(errno));
    m.buf.attach(m.fd, m.shown);
    return;
  }
  if (exists && S_ISDIR(st.st_mode)) throw InputError("--out " + m.shown + " is a directory");
  if (exists && !S_ISREG(st.st_mode)) throw InputError("--out " + m.shown + " is neither a file, a FIFO nor a character device");
  if (exists && ::access(p.c_str(), W_OK) != 0) throw InputError("cannot write " + m.shown + ": " + why(errno));
  // The temporary beside the target; for an existing file in a directory we may not write, in the
  // temporary directory (the file is then rewritten in place).
  m.fd = create_temp(p, m.temp);
  if (m.fd < 0 && exists) {
    std::error_code ec;
    m.fd = create_temp(fs::temp_directory_path(ec) / "stepwise-out", m.temp);
    m.mode = Impl::Mode::in_place;
  }
  if (m.fd < 0) {
    m.temp.clear();
    throw InputError("cannot write " + m.shown + ": " + why(errno));
  }
  register_temp(m.temp.string());
  m.buf.attach(m.fd, m.shown);
  if (m.mode == Impl::Mode::in_place) return;
  m.mode = Impl::Mode::rename;
  if (!exists) return;
  // Replacing: the temporary takes the target's owner and mode, or the target is rewritten in place.
  struct stat tst {};
  const bool owner_kept = ::fstat(m.fd, &tst) == 0 && ((tst.st_uid == st.st_uid && tst.st_gid == st.st_gid) || ::fchown(m.fd, st.st_uid, st.st_gid) == 0);
  if (st.st_nlink > 1 || !owner_kept || ::fchmod(m.fd, st.st_mode & 07777) != 0) m.mode = Impl::Mode::in_place;
}

OutputFile::~OutputFile() {
  Impl& m = *impl_;
  if (m.fd >= 0) ::close(m.fd);
  if (!m.committed) m.drop_temp();
}

std::ostream& OutputFile::stream() { return impl_->os; }

void OutputFile::commit() {
  Impl& m = *impl_;
  m.buf.flush_all();
  switch (m.mode) {
    case Impl::Mode::through: break;
    case Impl::Mode::rename:
      if (::close(std::exchange(m.fd, -1)) != 0) throw InputError("cannot write " + m.shown + ": " + why(errno));
      if (::rename(m.temp.c_str(), m.target.c_str()) != 0) throw InputError("cannot write " + m.shown + ": " + why(errno));
      unregister_temp(m.temp.string());
      m.temp.clear();
      break;
    case Impl::Mode::in_place:
      m.rewrite_in_place();
      m.drop_temp();
      break;
  }
  m.committed = true;
}

BudgetedStream::BudgetedStream(std::ostream& out, std::uint64_t max) : std::ostream(&buf_) {
  buf_.out = &out, buf_.max = max;
  exceptions(std::ios::badbit);  // the budget's InputError passes through
}

void BudgetedStream::Buf::count(std::streamsize n) {
  written += std::uint64_t(n);
  if (written > max) throw InputError("the output passes the budget of " + std::to_string(max) + " bytes (--max-output raises it)");
}

BudgetedStream::Buf::int_type BudgetedStream::Buf::overflow(int_type c) {
  if (c == traits_type::eof()) return c;
  count(1);
  out->put(char(c));
  return c;
}

std::streamsize BudgetedStream::Buf::xsputn(const char* s, std::streamsize n) {
  count(n);
  out->write(s, n);
  return n;
}

std::string stdout_error() {
  std::cout.flush();
  errno = 0;
  if (std::fflush(stdout) != 0 || std::ferror(stdout) || std::cout.fail()) return errno ? why(errno) : "it is closed or full";
  return {};
}

void guard_standard_descriptors() {
  for (int fd : {0, 1, 2}) {
    if (::fcntl(fd, F_GETFD) >= 0 || errno != EBADF) continue;
    int got = fd == 1 ? ::open("/dev/full", O_WRONLY) : -1;
    if (got < 0) got = ::open("/dev/null", fd == 0 ? O_RDONLY : O_WRONLY);
    if (got >= 0 && got != fd) ::dup2(got, fd), ::close(got);
  }
}

}  // namespace sw
