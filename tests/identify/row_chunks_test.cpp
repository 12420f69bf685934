#include "identify/row_chunks.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <stdexcept>
#include <vector>

namespace frictionid::row_chunks_test {
namespace {

TEST(RowChunks, EveryChunkRunsExactlyOnceWhateverTheThreadCount) {
  for (int threads : {1, 2, 3, 8}) {
    std::vector<std::atomic<int>> visits(1000);
    for_each_chunk(visits.size(), threads, [&](std::size_t c) { visits[c].fetch_add(1); });
    for (std::size_t c = 0; c < visits.size(); ++c) ASSERT_EQ(visits[c].load(), 1) << c;
  }
}

TEST(RowChunks, EveryTaskRunsExactlyOnceEvenWhenTasksAreFewerThanThreads) {
  for (std::size_t count : {0u, 1u, 2u, 4u, 9u})
    for (int threads : {1, 2, 8}) {
      std::vector<std::atomic<int>> visits(count);
      for_each_task(count, threads, [&](std::size_t c) { visits[c].fetch_add(1); });
      for (std::size_t c = 0; c < count; ++c) ASSERT_EQ(visits[c].load(), 1) << count << " " << c;
    }
}

TEST(RowChunks, AnExceptionInOneChunkReachesTheCaller) {
  EXPECT_THROW(for_each_chunk(100, 2,
                              [](std::size_t c) {
                                if (c == 37) throw std::runtime_error("chunk 37");
                              }),
               std::runtime_error);
}

TEST(RowChunks, ChunksCoverTheRowsWithTheLastOnePartial) {
  EXPECT_EQ(chunk_count(0), 0u);
  EXPECT_EQ(chunk_count(1), 1u);
  EXPECT_EQ(chunk_count(kChunkRows), 1u);
  EXPECT_EQ(chunk_count(kChunkRows + 1), 2u);
  EXPECT_GE(resolve_thread_count(0), 1);
  EXPECT_EQ(resolve_thread_count(3), 3);
}

}  // namespace
}  // namespace frictionid::row_chunks_test
