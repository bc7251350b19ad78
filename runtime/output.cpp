// Output files (AtomicFile) and the byte budget (BudgetedStream).
#include "output.hpp"
#include <unistd.h>
#include <csignal>
#include <cstring>
#include <random>

namespace sw {

namespace {

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

int register_temp(const std::string& path) {
  static const bool installed = [] {
    std::signal(SIGINT, remove_temps_and_die);
    std::signal(SIGTERM, remove_temps_and_die);
    return true;
  }();
  (void)installed;
  if (path.size() >= sizeof g_temps[0]) return -1;
  for (int k = 0; k < kMaxTemps; ++k)
    if (!g_temp_used[k]) {
      std::memcpy(g_temps[k], path.c_str(), path.size() + 1);
      g_temp_used[k] = 1;
      return k;
    }
  return -1;
}

void unregister_temp(const std::string& path) {
  for (int k = 0; k < kMaxTemps; ++k)
    if (g_temp_used[k] && path == g_temps[k]) g_temp_used[k] = 0;
}

// A symbolic link's final target (a chain of links, each relative to its own directory); bounded.
std::filesystem::path follow_links(std::filesystem::path p) {
  for (int hops = 0; hops < 40; ++hops) {
    std::error_code ec;
    if (!std::filesystem::is_symlink(std::filesystem::symlink_status(p, ec))) return p;
    const std::filesystem::path to = std::filesystem::read_symlink(p, ec);
    if (ec) throw InputError("cannot read the link " + p.string());
    p = to.is_absolute() ? to : p.parent_path() / to;
  }
  throw InputError("--out " + p.string() + ": too many levels of symbolic links");
}

}  // namespace

AtomicFile::AtomicFile(std::filesystem::path target) : target_(follow_links(std::move(target))) {
  std::error_code ec;
  const auto st = std::filesystem::status(target_, ec);
  using std::filesystem::file_type;
  if (st.type() == file_type::fifo || st.type() == file_type::character) {  // written through
    out_.open(target_, std::ios::binary);
    if (!out_) throw InputError("cannot write " + target_.string());
    return;
  }
  if (st.type() == file_type::directory) throw InputError("--out " + target_.string() + " is a directory");
  if (st.type() != file_type::not_found && st.type() != file_type::regular)
    throw InputError("--out " + target_.string() + " is neither a file, a FIFO nor a character device");
  std::random_device rd;
  temp_ = target_;
  temp_ += ".tmp-" + std::to_string(rd());
  register_temp(temp_.string());
  out_.open(temp_, std::ios::binary | std::ios::trunc);
  if (!out_) {
    unregister_temp(temp_.string());
    throw InputError("cannot write " + target_.string());
  }
}

AtomicFile::~AtomicFile() {
  if (committed_ || temp_.empty()) return;
  out_.close();
  std::error_code ec;
  std::filesystem::remove(temp_, ec);
  unregister_temp(temp_.string());
}

void AtomicFile::commit() {
  out_.close();
  if (!out_) throw InputError("cannot write " + target_.string());
  if (!temp_.empty()) {
    std::filesystem::rename(temp_, target_);
    unregister_temp(temp_.string());
  }
  committed_ = true;
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

}  // namespace sw
