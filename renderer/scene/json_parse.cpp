#include "scene/json_parse.h"

#include "io/message_text.h"
#include "scene/json_node.h"
#include "scene/load.h"

#include <set>
#include <vector>

namespace m3055::scene_json {

namespace {

// What nlohmann::json allocates, in bytes with glibc's malloc (a 16-byte
// header, 16-byte rounding) on a 64-bit system. An estimate, on the high side,
// of the document a text would become; tests/json_parse_test.cpp holds
// it against the measured peak.
constexpr std::size_t kSlot = 16;        // one json value inside an array's buffer
constexpr std::size_t kArray = 32 + 16;  // new std::vector, and its buffer's header
constexpr std::size_t kObject = 64;      // new std::map
constexpr std::size_t kMember = 96;      // a map node: tree links, key string, json value
constexpr std::size_t kString = 48;      // new std::string

std::size_t heap_bytes(std::size_t length) {  // a std::string's own buffer, beyond 15 chars
    return length <= 15 ? 0 : (length + 1 + 8 + 15) / 16 * 16;
}
std::size_t capacity(std::size_t count) {  // std::vector after push_back growth
    std::size_t c = 1;
    while (c < count) c *= 2;
    return count == 0 ? 0 : c;
}

// One SAX pass before the document is built: tracks where it is (one frame per
// open object or array) to report a duplicate key or deep nesting with its
// path, and adds up what the document would cost. The first such problem is
// kept and bookkeeping stops, but the pass reads on, so that a syntax error
// further on is still the one reported.
class Scanner : public nlohmann::json_sax<json> {
public:
    bool null() override { return element_done(); }
    bool boolean(bool) override { return element_done(); }
    bool number_integer(json::number_integer_t) override { return element_done(); }
    bool number_unsigned(json::number_unsigned_t) override { return element_done(); }
    bool number_float(json::number_float_t, const std::string&) override { return element_done(); }
    bool string(std::string& value) override {
        add(kString + heap_bytes(value.size()));
        return element_done();
    }
    bool binary(json::binary_t&) override { return element_done(); }
    bool start_object(std::size_t) override { return open(true, kObject); }
    bool start_array(std::size_t) override { return open(false, kArray); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }
    bool key(std::string& key) override {
        add(kMember + heap_bytes(key.size()));
        if (!problem_.empty()) return true;  // before, or just now: the frames are gone
        Frame& top = frames_.back();
        top.key = key;
        if (top.keys.size() >= kMaxKeys) return found(path() + ": has more than " + std::to_string(kMaxKeys) + " keys");
        if (!top.keys.insert(key).second) return found(child_path() + ": duplicate key");
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception& error) override {
        syntax_error_ = "invalid JSON: " + json_problem(error.what());
        return false;
    }

    // "" when the document may be built, else the problem (without the source).
    const std::string& problem() const { return syntax_error_.empty() ? problem_ : syntax_error_; }
    std::size_t bytes() const { return bytes_; }

private:
    // A frame holds only its own step, not its whole path: copying the path into
    // every frame made deeply nested input cost O(depth^2) memory (a 400 KB file
    // of '[' took gigabytes). The path is built only for a message.
    struct Frame {
        bool is_object;
        std::set<std::string> keys;
        std::string key;    // object: the key being read
        std::size_t index;  // array: the entry being read
    };

    std::string path() const {
        std::string walked;
        for (std::size_t i = 0; i + 1 < frames_.size(); ++i)
            walked = frames_[i].is_object ? join_key(walked, frames_[i].key) : join_index(walked, frames_[i].index);
        return walked.empty() ? "(root)" : text::one_line(walked, text::kMaxPathBytes);
    }
    std::string child_path() const {
        std::string walked;
        for (const Frame& frame : frames_)
            walked = frame.is_object ? join_key(walked, frame.key) : join_index(walked, frame.index);
        return text::one_line(walked, text::kMaxPathBytes);  // 64 levels of keys: cut in the middle
    }
    bool found(const std::string& problem) {
        problem_ = problem;
        frames_.clear();
        frames_.shrink_to_fit();
        return true;
    }
    void add(std::size_t bytes) {
        if (!problem_.empty()) return;
        bytes_ += bytes;
        if (bytes_ > kMaxDocumentBytes)
            found("too large: parsed, it would take more than " + std::to_string(kMaxDocumentBytes >> 20) +
                  " MiB of memory (too many objects, keys or values)");
    }
    bool open(bool is_object, std::size_t bytes) {
        if (!problem_.empty()) return true;
        if (frames_.size() >= kMaxNesting)
            return found(child_path() + ": nested deeper than " + std::to_string(kMaxNesting) + " levels");
        add(bytes);
        frames_.push_back(Frame{is_object, {}, {}, 0});
        return true;
    }
    bool close() {
        if (!problem_.empty()) return true;
        const Frame top = std::move(frames_.back());
        frames_.pop_back();
        if (!top.is_object) {
            // The buffer after the last doubling, and the one it replaced (freed, but
            // counted: the peak holds both for a moment).
            const std::size_t slots = capacity(top.index);
            add(kSlot * (slots + slots / 2));  // may find the document too large
        }
        return element_done();
    }
    bool element_done() {
        if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().index;
        return true;
    }

    std::vector<Frame> frames_;
    std::size_t bytes_ = kSlot;  // the root value
    std::string problem_, syntax_error_;
};

// A file saved as UTF-16 or UTF-32, or one that is not text at all, gets its
// own message instead of "invalid literal" on an unreadable byte.
std::string encoding_problem(const std::string& text) {
    const auto starts = [&](const char* bom, std::size_t n) { return text.compare(0, n, bom, n) == 0; };
    if (starts("\x00\x00\xFE\xFF", 4) || starts("\xFF\xFE\x00\x00", 4))
        return "is UTF-32 text (it starts with a byte order mark); save it as UTF-8";
    if (starts("\xFE\xFF", 2) || starts("\xFF\xFE", 2))
        return "is UTF-16 text (it starts with a byte order mark); save it as UTF-8";
    const std::size_t nul = text.find('\0');
    if (nul != std::string::npos)
        return "holds a NUL byte at byte " + std::to_string(nul) +
               ": not UTF-8 text (UTF-16, UTF-32 or a binary file?)";
    return "";
}

}  // namespace

DocumentScan scan_document(const std::string& text) {
    if (std::string problem = encoding_problem(text); !problem.empty()) return {problem, 0};
    Scanner scanner;
    json::sax_parse(text, &scanner);
    return {scanner.problem(), scanner.bytes()};
}

json parse_document(const std::string& text, const std::string& source) {
    const DocumentScan scan = scan_document(text);
    if (!scan.problem.empty()) throw SceneError(source + ": " + scan.problem);
    // Valid, small enough, no duplicate: built with nlohmann's own (faster) parser.
    return json::parse(text);
}

}  // namespace m3055::scene_json
