// passes/draw_chunks.h: the chunks a render with a deadline draws cover the
// same elements in the same order as one draw, each within the budget unless
// it is a single element (then it is banded), and the bands cover the rows
// once each. Pixel identity of chunked renders: tests/untrusted_time_test.cpp.
#include "passes/draw_chunks.h"

#include <gtest/gtest.h>

#include <random>

namespace m3055 {
namespace {

TEST(DrawChunks, CoverEveryElementOnceInOrderWithinBudget) {
    std::mt19937 random(5);
    for (int round = 0; round < 500; ++round) {
        const std::size_t granule = round % 2 ? 3 : 1;
        std::vector<DrawSpan> spans;
        std::size_t next = 0;
        const int n = int(random() % 50);
        for (int i = 0; i < n; ++i) {
            const std::size_t count = granule * (1 + random() % 20);
            const double work = std::pow(10.0, double(random() % 90) / 10.0);  // 1 to 1e9
            const int row0 = int(random() % 100);
            spans.push_back({next, count, work, row0, row0 + int(random() % 100)});
            next += count;
        }
        const double budget = 1e6;
        const std::vector<DrawSpan> chunks = plan_chunks(spans, budget, granule);
        std::size_t expected_first = 0;
        double total = 0, chunked_total = 0;
        for (const DrawSpan& span : spans) total += span.work;
        for (const DrawSpan& chunk : chunks) {
            EXPECT_EQ(chunk.first, expected_first);
            EXPECT_GT(chunk.count, 0u);
            EXPECT_EQ(chunk.count % granule, 0u);
            if (chunk.count > granule) {
                EXPECT_LE(chunk.work, budget * (1 + 1e-12));
            }
            expected_first += chunk.count;
            chunked_total += chunk.work;
            // Bands: consecutive, covering the chunk's rows once.
            const std::vector<int> rows = band_rows(chunk, budget);
            ASSERT_GE(rows.size(), 2u);
            EXPECT_EQ(rows.front(), chunk.row0);
            EXPECT_EQ(rows.back(), chunk.row0 + std::max(chunk.row1 - chunk.row0, 1));
            for (std::size_t b = 1; b < rows.size(); ++b) EXPECT_LT(rows[b - 1], rows[b]);
            const double per_band = chunk.work / double(rows.size() - 1);
            if (std::size_t(chunk.row1 - chunk.row0) > rows.size() - 1) {
                EXPECT_LE(per_band, budget * 1.05);
            }
        }
        EXPECT_EQ(expected_first, next);
        EXPECT_NEAR(chunked_total, total, total * 1e-9 + 1e-9);
    }
}

TEST(DrawChunks, SmallSpansMergeIntoOneChunk) {
    const std::vector<DrawSpan> chunks = plan_chunks({{0, 1, 10, 0, 5}, {1, 1, 10, 3, 9}, {2, 1, 10, 1, 2}}, 1e6, 1);
    ASSERT_EQ(chunks.size(), 1u);
    EXPECT_EQ(chunks[0].count, 3u);
    EXPECT_EQ(chunks[0].row0, 0);
    EXPECT_EQ(chunks[0].row1, 9);
    EXPECT_EQ(band_rows(chunks[0], 1e6), (std::vector<int>{0, 9}));
}

}  // namespace
}  // namespace m3055
