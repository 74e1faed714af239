#include "scene/json_parse.h"

#include "scene/json_node.h"
#include "scene/load.h"

#include <set>
#include <vector>

namespace m3055::scene_json {

namespace {

// Where the parser is: one frame per open object or array, so a duplicate key
// can be reported with its full path.
class PathTracker {
public:
    explicit PathTracker(const std::string& source) : source_(source) {}

    bool on_event(json::parse_event_t event, const json& parsed) {
        switch (event) {
            case json::parse_event_t::object_start:
            case json::parse_event_t::array_start:
                frames_.push_back(Frame{event == json::parse_event_t::object_start, child_path(), {}, {}, 0});
                break;
            case json::parse_event_t::key: {
                Frame& top = frames_.back();
                top.key = parsed.get<std::string>();
                if (!top.keys.insert(top.key).second)
                    throw SceneError(source_ + ": " + child_path() + ": duplicate key");
                break;
            }
            case json::parse_event_t::object_end:
            case json::parse_event_t::array_end:
                frames_.pop_back();
                element_done();
                break;
            case json::parse_event_t::value:
                element_done();
                break;
        }
        return true;  // keep everything
    }

private:
    struct Frame {
        bool is_object;
        std::string path;
        std::set<std::string> keys;
        std::string key;    // object: the key being read
        std::size_t index;  // array: the entry being read
    };

    std::string child_path() const {
        if (frames_.empty()) return "";
        const Frame& top = frames_.back();
        return top.is_object ? join_key(top.path, top.key) : join_index(top.path, top.index);
    }

    void element_done() {
        if (!frames_.empty() && !frames_.back().is_object) ++frames_.back().index;
    }

    const std::string& source_;
    std::vector<Frame> frames_;
};

}  // namespace

json parse_document(const std::string& text, const std::string& source) {
    PathTracker tracker(source);
    try {
        return json::parse(text, [&](int, json::parse_event_t event, json& parsed) {
            return tracker.on_event(event, parsed);
        });
    } catch (const json::exception& error) {
        throw SceneError(source + ": invalid JSON: " + json_problem(error.what()));
    }
}

}  // namespace m3055::scene_json
