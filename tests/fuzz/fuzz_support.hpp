// Shared helpers for the libFuzzer targets: a scratch file that holds the current input.
#pragma once

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

namespace frictionid::fuzz {

// A temporary file (one per process, removed at exit) that write() fills with the input bytes.
// It lives in $FUZZ_SCRATCH_DIR, else /dev/shm when present (rewriting a file on a disk-backed
// ext4 flushes it on every close), else $TMPDIR or /tmp.
class ScratchFile {
 public:
  explicit ScratchFile(const char* suffix) {
    std::string dir = "/tmp";
    if (const char* tmp = std::getenv("TMPDIR"); tmp && *tmp) dir = tmp;
    if (::access("/dev/shm", W_OK) == 0) dir = "/dev/shm";
    if (const char* d = std::getenv("FUZZ_SCRATCH_DIR"); d && *d) dir = d;
    path_ = dir + "/frictionid_fuzz_XXXXXX" + suffix;
    const int fd = ::mkstemps(path_.data(), static_cast<int>(std::string(suffix).size()));
    if (fd < 0) std::abort();
    ::close(fd);
  }
  ~ScratchFile() { std::remove(path_.c_str()); }
  ScratchFile(const ScratchFile&) = delete;
  ScratchFile& operator=(const ScratchFile&) = delete;

  const std::string& write(const unsigned char* data, std::size_t size) {
    std::FILE* f = std::fopen(path_.c_str(), "wb");
    if (!f) std::abort();
    if (size > 0 && std::fwrite(data, 1, size, f) != size) std::abort();
    if (std::fclose(f) != 0) std::abort();
    return path_;
  }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

// Stops the fuzzer with a message when an invariant of an accepted input does not hold.
#define FRICTIONID_FUZZ_CHECK(cond)                                                        \
  do {                                                                                     \
    if (!(cond)) {                                                                         \
      std::fprintf(stderr, "invariant violated: %s (%s:%d)\n", #cond, __FILE__, __LINE__); \
      std::abort();                                                                        \
    }                                                                                      \
  } while (0)

}  // namespace frictionid::fuzz
