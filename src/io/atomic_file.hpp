// Writes a whole file or nothing: content goes to a temporary file in the same directory, is
// flushed, then renamed over the target, so a crash or an error never leaves a half-written file.
//
// Outputs that are not regular files are never replaced by a regular one: a FIFO, a device, a
// socket or anything under /dev (but /dev/shm) or /proc is written through, appended to, without
// atomicity. A name of a descriptor the process already has (/dev/stdout, /dev/fd/63 from the
// shell's `>(cmd)`, /proc/self/fd/1, or a symlink to one) is written to that descriptor at its
// offset, as a shell redirection writes: `--output /dev/stdout >> log` appends to log. A symlink
// stays a symlink and its target is replaced atomically instead.
#pragma once

#include <string>

namespace frictionid {

// When the content reaches the disk: `Now` fsyncs it before the rename; `Later` leaves that to
// the caller, who syncs the file system afterwards (syncfs), as `batch` does for a group of runs.
// Either way a reader sees the old file or the whole new one, never part of one.
enum class Flush { Now, Later };

// Throws std::runtime_error (with the path and the system's reason) on failure; the temporary
// file is removed in that case.
void write_file_atomically(const std::string& path, const std::string& content,
                           Flush flush = Flush::Now);

// Removes the temporary files that write_file_atomically left in `dir` when it was killed
// between creating one and renaming it (".NAME.tmp.XXXXXX"); only for a directory the caller
// holds the lock of, where no other writer can be at work. Returns how many it removed.
int remove_atomic_leftovers(const std::string& dir);

}  // namespace frictionid
