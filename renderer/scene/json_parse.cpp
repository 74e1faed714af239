#include "scene/json_parse.h"

#include "scene/json_node.h"
#include "scene/load.h"

#include <set>
#include <vector>

namespace m3055::scene_json {

namespace {

// A SAX pass that only tracks where it is (one frame per open object or array),
// so that a duplicate key can be reported with its full path. A separate pass
// because nlohmann's callback parser is ~20x slower than plain parsing.
class DuplicateKeyFinder : public nlohmann::json_sax<json> {
public:
    explicit DuplicateKeyFinder(const std::string& source) : source_(source) {}

    bool null() override { return element_done(); }
    bool boolean(bool) override { return element_done(); }
    bool number_integer(json::number_integer_t) override { return element_done(); }
    bool number_unsigned(json::number_unsigned_t) override { return element_done(); }
    bool number_float(json::number_float_t, const std::string&) override { return element_done(); }
    bool string(std::string&) override { return element_done(); }
    bool binary(json::binary_t&) override { return element_done(); }
    bool start_object(std::size_t) override { return open(true); }
    bool start_array(std::size_t) override { return open(false); }
    bool end_object() override { return close(); }
    bool end_array() override { return close(); }
    bool key(std::string& key) override {
        Frame& top = frames_.back();
        top.key = key;
        if (!top.keys.insert(key).second) throw SceneError(source_ + ": " + child_path() + ": duplicate key");
        return true;
    }
    bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) override {
        return false;  // cannot happen: the text was parsed successfully before
    }

private:
    // A frame holds only its own step, not its whole path: copying the path into
    // every frame made deeply nested input cost O(depth^2) memory (a 400 KB file
    // of '[' took gigabytes). The path is built only when a duplicate is found.
    struct Frame {
        bool is_object;
        std::set<std::string> keys;
        std::string key;    // object: the key being read
        std::size_t index;  // array: the entry being read
    };

    std::string child_path() const {
        std::string path;
        for (const Frame& frame : frames_)
            path = frame.is_object ? join_key(path, frame.key) : join_index(path, frame.index);
        return path;
    }
    bool open(bool is_object) {
        if (frames_.size() >= kMaxNesting)
            throw SceneError(source_ + ": " + child_path() + ": nested deeper than " +
                             std::to_string(kMaxNesting) + " levels");
        frames_.push_back(Frame{is_object, {}, {}, 0});
        return true;
    }
    bool close() {
        frames_.pop_back();
        return element_done();
    }
    bool element_done() {
        if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().index;
        return true;
    }

    const std::string& source_;
    std::vector<Frame> frames_;
};

}  // namespace

json parse_document(const std::string& text, const std::string& source) {
    json doc;
    try {
        doc = json::parse(text);
    } catch (const json::exception& error) {
        throw SceneError(source + ": invalid JSON: " + json_problem(error.what()));
    }
    DuplicateKeyFinder finder(source);
    json::sax_parse(text, &finder);
    return doc;
}

}  // namespace m3055::scene_json
