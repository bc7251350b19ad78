// Output files and streams: --out written the way cp and tee treat their target, and the
// --max-output byte budget (docs/cli.md#output-files).
#pragma once
#include <cstdint>
#include <filesystem>
#include <memory>
#include <ostream>
#include <streambuf>
#include <string>
#include "input.hpp"

namespace sw {

// An output file (--out). Nothing reaches a regular file until commit(), so an error on the way
// (bad input, a budget, a signal) leaves the target as it was:
// - a new file is written under a temporary name beside it and renamed into place by commit();
// - an existing regular file keeps its inode, mode and owner, as cp and tee keep them: it is
//   replaced by that rename when it has one link and the temporary can take its mode and owner,
//   else rewritten in place once the whole output is ready (its other hard links see the new
//   content); one the user may not write is refused;
// - a symbolic link is followed to its final target, and the link stays;
// - a path that names an open descriptor (/dev/stdout, /dev/stderr, /dev/fd/N, /proc/self/fd/N)
//   is written through that descriptor as it was opened (a `>> log` appends), never renamed over;
// - a FIFO or a character device is written through, in place;
// - a directory, a socket or a block device is refused (InputError).
// Every write is checked: a full disk or a closed descriptor is an InputError naming the path.
class OutputFile {
 public:
  explicit OutputFile(std::filesystem::path target);
  ~OutputFile();
  OutputFile(const OutputFile&) = delete;
  OutputFile& operator=(const OutputFile&) = delete;
  std::ostream& stream();
  void commit();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// A stream that passes bytes on to `out` and throws InputError once more than `max` have passed
// (naming --max-output). The caller's OutputFile then leaves no file behind.
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

// Standard output for a command's results: flushes std::cout and stdio, and says why what was
// written to it did not all reach it (a full disk, /dev/full, a closed descriptor); empty if it did.
std::string stdout_error();
// Makes descriptors 0, 1 and 2 open at start-up: a closed one is opened on /dev/null (stdin,
// stderr) or /dev/full (stdout, so that a command that writes results there fails visibly rather
// than writing them into the first file it opens).
void guard_standard_descriptors();

}  // namespace sw
