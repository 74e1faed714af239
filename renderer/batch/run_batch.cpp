#include "batch/run_batch.h"

#include "frame/render_error.h"
#include "image/image.h"
#include "io/message_text.h"
#include "io/run_files.h"
#include "scene/load.h"

#include <malloc.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <future>
#include <memory>
#include <mutex>
#include <thread>

namespace m3055 {
namespace {

// Runs jobs on worker threads; each job's future holds "" or its error line.
class EncoderPool {
public:
    explicit EncoderPool(unsigned threads) {
        for (unsigned i = 0; i < threads; ++i) workers_.emplace_back([this]() { work(); });
    }
    ~EncoderPool() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            stopping_ = true;
        }
        wake_.notify_all();
        for (auto& worker : workers_) worker.join();
    }
    std::future<std::string> submit(std::function<void()> job) {
        std::packaged_task<std::string()> task([job = std::move(job)]() -> std::string {
            try {
                job();
                return "";
            } catch (const std::exception& e) {
                return e.what();
            }
        });
        std::future<std::string> result = task.get_future();
        {
            std::lock_guard<std::mutex> lock(mutex_);
            jobs_.push_back(std::move(task));
        }
        wake_.notify_one();
        return result;
    }

private:
    void work() {
        for (;;) {
            std::packaged_task<std::string()> task;
            {
                std::unique_lock<std::mutex> lock(mutex_);
                wake_.wait(lock, [this]() { return stopping_ || !jobs_.empty(); });
                if (jobs_.empty()) return;  // stopping, and nothing left to do
                task = std::move(jobs_.front());
                jobs_.pop_front();
            }
            task();
        }
    }
    std::vector<std::thread> workers_;
    std::deque<std::packaged_task<std::string()>> jobs_;
    std::mutex mutex_;
    std::condition_variable wake_;
    bool stopping_ = false;
};

}  // namespace

void check_batch_files(std::vector<BatchItem>& items, const std::string& manifest, const std::string& report) {
    constexpr io::RunFiles::Owner kManifest = ~io::RunFiles::Owner(0);
    io::RunFiles files;
    if (!manifest.empty()) files.add_input(kManifest, "the manifest", manifest);
    constexpr io::RunFiles::Owner kReport = kManifest - 1;
    if (!report.empty()) files.add_output(kReport, "--report", report);
    for (std::size_t i = 0; i < items.size(); ++i) {
        const std::string entry = "[" + std::to_string(items[i].entry) + "]";
        files.add_input(i, entry + ".scene", items[i].scene);
        files.add_output(i, entry + ".out", items[i].out);
        if (!items[i].raw.empty()) files.add_output(i, entry + ".raw", items[i].raw);
    }
    const std::string prefix = manifest.empty() ? "" : text::quote_name(manifest) + ": ";
    const std::map<io::RunFiles::Owner, std::string> problems = files.check(prefix);
    // A report that cannot be written, or would overwrite an input or an output, stops the run.
    if (const auto it = problems.find(kReport); it != problems.end()) throw std::runtime_error(it->second);
    for (const auto& [owner, problem] : problems)
        if (owner != kManifest && items[owner].problem.empty()) items[owner].problem = problem;
}

namespace {

// Bytes an item's images hold until they are written: the 8-bit display, its
// PNG (at most about as large), and the raw floats (written from the image
// itself, image.h: pfm_file).
std::size_t images_in_flight(int width, int height, bool raw) {
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    return pixels * 3 * 2 + (raw ? pixels * 12 : 0);
}

// Pass 1: every scene is loaded, and dropped, before anything is drawn, with
// no GL context yet. A broken or hostile scene is refused at the memory cost
// of loading it alone (docs/limits.md), its line comes at once, and a
// manifest of broken scenes never starts a context. Returns each item's error.
std::vector<std::string> check_scenes(const std::vector<BatchItem>& items, const LoadContext& scenes) {
    std::vector<std::string> errors(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!items[i].problem.empty()) {
            errors[i] = items[i].problem;  // its files clash: not even read
            continue;
        }
        try {
            load_scene_file(items[i].scene, scenes);
        } catch (const std::exception& e) {
            errors[i] = e.what();
        }
    }
#ifdef __GLIBC__
    // What loading freed goes back to the system before the GL context is
    // made, instead of staying in the heap's free lists under it.
    malloc_trim(0);
#endif
    return errors;
}

}  // namespace

std::size_t run_batch(const std::function<Capture&()>& capture, const std::vector<BatchItem>& items,
                      const LoadContext& scenes, const BatchProgress& progress, const BatchOptions& options) {
    std::size_t failures = 0;
    const std::vector<std::string> errors = check_scenes(items, scenes);
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (errors[i].empty()) continue;
        ++failures;
        if (progress) progress(i, items[i], errors[i]);
    }

    // Pass 2: the scenes that loaded, rendered in manifest order.
    const unsigned encoder_threads =
        options.encoder_threads ? options.encoder_threads : std::max(1u, std::thread::hardware_concurrency());
    EncoderPool pool(encoder_threads);
    // Results in flight, oldest first, with the bytes their images hold;
    // bounded in count and in bytes, so that finished images do not pile up in
    // memory when encoding is slower than rendering: six 8192 x 8192 scenes
    // with --raw are in memory one at a time, not all at once.
    struct Pending {
        std::size_t index, bytes;
        std::future<std::string> result;
    };
    std::deque<Pending> pending;
    std::size_t bytes_in_flight = 0;
    const std::size_t max_pending = 2 * std::size_t(encoder_threads);
    auto report_front = [&]() {
        Pending front = std::move(pending.front());
        pending.pop_front();
        const std::string error = front.result.get();
        bytes_in_flight -= front.bytes;
        if (!error.empty()) ++failures;
        if (progress) progress(front.index, items[front.index], error);
    };
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (!errors[i].empty()) continue;
        const BatchItem& item = items[i];
        std::promise<std::string> failed;
        try {
            const auto start = std::chrono::steady_clock::now();
            const Scene scene = load_scene_file(item.scene, scenes);
            Renderer& renderer = capture().renderer();
            renderer.set_deadline(scene_deadline(start, options.scene_timeout_s));
            try {
                renderer.render(scene);
            } catch (const RenderTimeout&) {
                throw std::runtime_error(over_budget_message(item.scene, options.scene_timeout_s));
            }
            // Read back only once the images already in flight leave room
            // (always when none is: one scene's images may exceed the budget).
            const std::size_t bytes = images_in_flight(renderer.width(), renderer.height(), !item.raw.empty());
            while (!pending.empty() && bytes_in_flight + bytes > options.image_memory_budget) report_front();
            // The same steps, and so the same bytes, as Capture::render_to_files.
            auto display = std::make_shared<Rgb8Image>(renderer.read_display());
            auto raw = std::make_shared<RgbFloatImage>();
            const bool check_finite = may_render_nonfinite(scene);  // a .brdf material
            if (!item.raw.empty() || check_finite) *raw = renderer.read_raw();
            if (check_finite)
                if (const NonFinite nonfinite = count_nonfinite(*raw); nonfinite.pixels > 0 && options.warned)
                    options.warned(i, item, nonfinite_warning(item.scene, nonfinite));
            if (item.raw.empty()) *raw = RgbFloatImage();
            bytes_in_flight += bytes;
            pending.push_back({i, bytes, pool.submit([&item, display, raw, &options]() {
                                   write_capture_files(item.out, *display, item.raw, *raw, options.on_written);
                               })});
        } catch (const ShaderError&) {
            throw;  // a broken build fails every scene: the batch stops, the log printed whole
        } catch (const std::exception& e) {
            failed.set_value(e.what());
            pending.push_back({i, 0, failed.get_future()});
        }
        while (!pending.empty() &&
               (pending.size() > max_pending ||
                pending.front().result.wait_for(std::chrono::seconds(0)) == std::future_status::ready))
            report_front();
    }
    while (!pending.empty()) report_front();
    return failures;
}

}  // namespace m3055
