#include "passes/draw_chunks.h"

#include <algorithm>
#include <cmath>

namespace m3055 {

std::vector<DrawSpan> plan_chunks(const std::vector<DrawSpan>& spans, double budget, std::size_t granule) {
    std::vector<DrawSpan> chunks;
    DrawSpan open;
    bool empty = true;
    const auto close = [&]() {
        if (!empty) chunks.push_back(open);
        empty = true;
    };
    for (const DrawSpan& span : spans) {
        if (span.count == 0) continue;
        if (span.work <= budget) {
            if (!empty && open.work + span.work > budget) close();
            if (empty) {
                open = span;
                empty = false;
                continue;
            }
            open.count += span.count;
            open.work += span.work;
            open.row0 = std::min(open.row0, span.row0);
            open.row1 = std::max(open.row1, span.row1);
            continue;
        }
        // Too much for one chunk: equal parts of whole granules, each alone.
        close();
        const std::size_t granules = (span.count + granule - 1) / granule;
        const std::size_t per_part =
            std::max<std::size_t>(1, std::size_t(std::floor(double(granules) * budget / span.work))) * granule;
        for (std::size_t done = 0; done < span.count; done += per_part) {
            DrawSpan part = span;
            part.first = span.first + done;
            part.count = std::min(per_part, span.count - done);
            part.work = span.work * double(part.count) / double(span.count);
            chunks.push_back(part);
        }
    }
    close();
    return chunks;
}

std::vector<int> band_rows(const DrawSpan& chunk, double budget) {
    const int rows = std::max(chunk.row1 - chunk.row0, 1);
    // Rows per band so that a band's share of the work stays within budget
    // (at least one row: a row cannot be split).
    const int per_band = chunk.work <= budget ? rows : std::max(1, int(std::floor(double(rows) * budget / chunk.work)));
    std::vector<int> starts;
    for (int row = chunk.row0; row < chunk.row0 + rows; row += per_band) starts.push_back(row);
    starts.push_back(chunk.row0 + rows);
    return starts;
}

void ChunkedDraws::check_deadline() const {
    if (deadline_ && std::chrono::steady_clock::now() > *deadline_) throw RenderTimeout("over its time budget");
}

void ChunkedDraws::between_draws() const {
    if (!deadline_) return gl_.Flush();
    gl_.Finish();
    check_deadline();
}

DrawSpan ChunkedDraws::span_of(std::size_t first, std::size_t count, std::size_t primitives, const float* rect,
                               std::size_t lights) const {
    DrawSpan span{first, count, kPrimitiveWork * double(primitives), 0, height_};
    if (rect) {
        span.row0 = std::clamp(int(std::floor((rect[1] + 1.0f) * 0.5f * float(height_))), 0, height_);
        span.row1 = std::clamp(int(std::ceil((rect[3] + 1.0f) * 0.5f * float(height_))), 0, height_);
    }
    const double pixels = rect ? 0.25 * double(rect[2] - rect[0]) * width_ * double(rect[3] - rect[1]) * height_
                               : double(width_) * height_;
    span.work += pixels * double(1 + lights);
    return span;
}

}  // namespace m3055
