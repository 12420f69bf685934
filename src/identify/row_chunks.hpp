// Rows are processed in fixed chunks whose boundaries do not depend on the thread count, and
// per-chunk results are combined in chunk order: a fit gives the same bits on 1 or 16 threads.
#pragma once

#include <cstddef>
#include <functional>

namespace frictionid {

inline constexpr std::size_t kChunkRows = 256;

inline std::size_t chunk_count(std::size_t rows) {
  return (rows + kChunkRows - 1) / kChunkRows;
}

// Calls work(chunk) once for every chunk in [0, count), on up to `threads` threads (the caller's
// among them). Which thread runs a chunk varies; work must write only to its chunk's slot. An
// exception thrown by work is rethrown here after every thread has finished.
void for_each_chunk(std::size_t count, int threads, const std::function<void(std::size_t)>& work);

// The same for a few large independent tasks (such as the channels of a dataset), which are
// worth a thread each.
void for_each_task(std::size_t count, int threads, const std::function<void(std::size_t)>& work);

// The thread count `0` stands for: every hardware thread.
int resolve_thread_count(int requested);

}  // namespace frictionid
