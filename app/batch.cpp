#include "batch.h"

#include "image/image.h"
#include "scene/load.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <deque>
#include <filesystem>
#include <fstream>
#include <functional>
#include <future>
#include <map>
#include <memory>
#include <mutex>
#include <sstream>
#include <thread>
#include <tuple>

namespace m3055 {
namespace {

namespace fs = std::filesystem;

// A manifest path relative to its folder; absolute paths are kept as written.
std::string resolve(const fs::path& folder, const std::string& path) {
    const fs::path p(path);
    return p.is_absolute() ? p.string() : (folder / p).lexically_normal().string();
}

// The string at `key` of entry `index`, or "" when absent and optional.
std::string read_path(const nlohmann::json& entry, const char* key, bool required, const std::string& prefix) {
    const auto found = entry.find(key);
    if (found == entry.end()) {
        if (required) throw ManifestError(prefix + "." + key + ": is required");
        return "";
    }
    if (!found->is_string()) throw ManifestError(prefix + "." + key + ": must be a string, got " + found->dump());
    if (found->get<std::string>().empty()) throw ManifestError(prefix + "." + key + ": must not be empty");
    return found->get<std::string>();
}

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

std::vector<BatchItem> load_manifest(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw ManifestError(path + ": cannot read the file");
    std::stringstream text;
    text << file.rdbuf();
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text.str());
    } catch (const nlohmann::json::parse_error& error) {
        throw ManifestError(path + ": invalid JSON at byte " + std::to_string(error.byte));
    }
    if (!doc.is_array()) throw ManifestError(path + ": must be a JSON array of {\"scene\", \"out\", \"raw\"} objects");

    const fs::path folder = fs::path(path).parent_path();
    std::vector<BatchItem> items;
    std::map<std::string, std::size_t> first_writer;  // output file -> entry that writes it
    for (std::size_t i = 0; i < doc.size(); ++i) {
        const std::string prefix = path + ": [" + std::to_string(i) + "]";
        const nlohmann::json& entry = doc[i];
        if (!entry.is_object()) throw ManifestError(prefix + ": must be an object, got " + entry.dump());
        for (const auto& [key, value] : entry.items()) {
            (void)value;
            if (key != "scene" && key != "out" && key != "raw")
                throw ManifestError(prefix + "." + key + ": unknown key (expected scene, out, raw)");
        }
        BatchItem item;
        item.scene = resolve(folder, read_path(entry, "scene", true, prefix));
        const std::string out = read_path(entry, "out", true, prefix);
        const std::string raw = read_path(entry, "raw", false, prefix);
        item.out = resolve(folder, out);
        if (!raw.empty()) item.raw = resolve(folder, raw);
        // Two entries writing one file would make the result depend on the order.
        for (const auto& [key, written, target] :
             {std::tuple{"out", out, item.out}, std::tuple{"raw", raw, item.raw}}) {
            if (target.empty()) continue;
            const auto [it, inserted] = first_writer.emplace(target, i);
            if (!inserted)
                throw ManifestError(prefix + "." + key + ": " + written + " is also written by entry [" +
                                    std::to_string(it->second) + "]");
        }
        items.push_back(item);
    }
    return items;
}

std::size_t run_batch(Capture& capture, const std::vector<BatchItem>& items, const BatchProgress& progress,
                      unsigned encoder_threads, const std::function<bool()>& stop) {
    if (encoder_threads == 0) encoder_threads = std::max(1u, std::thread::hardware_concurrency());
    EncoderPool pool(encoder_threads);
    // Results in flight, oldest first; bounded so that finished images do not
    // pile up in memory when encoding is slower than rendering.
    std::deque<std::pair<std::size_t, std::future<std::string>>> pending;
    const std::size_t max_pending = 2 * std::size_t(encoder_threads);
    std::size_t failures = 0;
    auto report_front = [&]() {
        const std::size_t index = pending.front().first;
        const std::string error = pending.front().second.get();
        pending.pop_front();
        if (!error.empty()) ++failures;
        if (progress) progress(index, items[index], error);
    };
    for (std::size_t i = 0; i < items.size(); ++i) {
        if (stop && stop()) break;  // the pending writes below still finish
        const BatchItem& item = items[i];
        std::promise<std::string> failed;
        try {
            Renderer& renderer = capture.renderer();
            renderer.render(load_scene_file(item.scene));
            // The same steps, and so the same bytes, as Capture::render_to_files.
            auto display = std::make_shared<Rgb8Image>(renderer.read_display());
            auto raw = std::make_shared<RgbFloatImage>();
            if (!item.raw.empty()) *raw = renderer.read_raw();
            pending.emplace_back(i, pool.submit([item, display, raw]() {
                write_capture_files(item.out, *display, item.raw, *raw);
            }));
        } catch (const std::exception& e) {
            failed.set_value(e.what());
            pending.emplace_back(i, failed.get_future());
        }
        while (!pending.empty() &&
               (pending.size() > max_pending ||
                pending.front().second.wait_for(std::chrono::seconds(0)) == std::future_status::ready))
            report_front();
    }
    while (!pending.empty()) report_front();
    return failures;
}

}  // namespace m3055
