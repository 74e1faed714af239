// The functions page.js calls (docs/web.md "Test API" and the page's own
// controls). Each is synchronous here; page.js wraps them in Promises. A
// returned string lives until the next call of the same function.
#include "app/web/page.h"
#include "explore/add_model.h"
#include "explore/apply.h"
#include "explore/brdf_files.h"
#include "explore/explorer.h"
#include "explore/files.h"
#include "explore/practice.h"
#include "explore/share_link.h"
#include "explore/start.h"
#include "grading/assignment.h"
#include "gl/program.h"
#include "image/image.h"
#include "io/message_text.h"
#include "scene/load.h"

#include <emscripten.h>

#include <exception>
#include <filesystem>
#include <memory>
#include <string>
#include <system_error>
#include <vector>

namespace m3055::web {

namespace {
std::unique_ptr<ExplorerSession> g_session;
}

ExplorerSession* session() { return g_session.get(); }
void set_session(std::unique_ptr<ExplorerSession> session) { g_session = std::move(session); }

}  // namespace m3055::web

using namespace m3055;

extern "C" {

// Loads the scene file `path` (in the work folder) as the explorer's scene
// and renders it. "" on success; else the line `m3055 render --scene PATH`
// prints for it (the previous scene stays when the file does not load).
EMSCRIPTEN_KEEPALIVE const char* m3055_load_scene(const char* path) {
    static std::string result;
    result.clear();
    ExplorerSession* s = web::session();
    if (!s) return result.assign("m3055: the explorer did not start").c_str();
    explore::Explorer& explorer = s->explorer();
    if (!explore::run_command(explorer, explore::command::LoadScene{path}))
        return result.assign(text::one_line("m3055: " + explorer.session.messages.load_error)).c_str();
    try {
        s->render_display_now();
    } catch (const std::exception& e) {
        result = error_text(e);
    }
    return result.c_str();
}

// A picked or dropped file: a .brdf opens on the selected object, a model
// file (.obj, .gltf, .glb) is added standing on the floor, anything else
// loads as a scene. "" or the error (also shown in the explorer).
EMSCRIPTEN_KEEPALIVE const char* m3055_open_file(const char* path) {
    static std::string result;
    result.clear();
    ExplorerSession* s = web::session();
    if (!s) return result.assign("m3055: the explorer did not start").c_str();
    explore::Explorer& explorer = s->explorer();
    const bool brdf = explore::is_brdf_path(path);
    const bool ok = explore::run_command(explorer, explore::dropped_file_command(path));
    const explore::Messages& messages = explorer.session.messages;
    if (!ok) result = brdf ? messages.brdf_error : messages.load_error;
    explorer.session.render_needed = true;
    return result.c_str();
}

// The PNG `m3055 render` writes for the scene as it is now, as a data: URL;
// on a render error, "" (m3055_last_error says why).
EMSCRIPTEN_KEEPALIVE const char* m3055_display_png(void) {
    static std::string result, error;
    result.clear();
    ExplorerSession* s = web::session();
    if (!s) return result.c_str();
    try {
        const std::vector<std::uint8_t> png = encode_png(s->render_display_now());
        result = "data:image/png;base64," + explore::base64_encode(std::string(png.begin(), png.end()));
    } catch (const std::exception& e) {
        s->explorer().session.messages.error = error_text(e);
    }
    return result.c_str();
}

// The explorer's last error line ("" when none).
EMSCRIPTEN_KEEPALIVE const char* m3055_last_error(void) {
    ExplorerSession* s = web::session();
    return s ? s->explorer().session.messages.error.c_str() : "";
}

// The share link's fragment for the scene as it is now: "scene=TOKEN".
EMSCRIPTEN_KEEPALIVE const char* m3055_share_fragment(void) {
    static std::string result;
    result.clear();
    if (ExplorerSession* s = web::session()) {
        try {
            result = "scene=" + explore::share_token(s->explorer().doc.scene, web::kWorkFolder);
        } catch (const std::exception& e) {
            s->explorer().session.messages.error = e.what();
        }
    }
    return result.c_str();
}

// A share link's token unpacked into the work folder: the scene as `path` (a
// scene file main() then starts with), the .brdf files it carries beside it
// under their names, and the scene loaded once as the explorer will load it.
// "" or the one-line reason, the loader's for a scene it refuses (nothing
// left written then: the page starts on the spec example).
EMSCRIPTEN_KEEPALIVE const char* m3055_unpack_share_token(const char* token, const char* path) {
    static std::string result;
    result.clear();
    std::vector<std::filesystem::path> written;
    try {
        const explore::SharedScene shared = explore::unpack_share_token(token);
        const std::filesystem::path scene = path, folder = scene.parent_path();
        for (const explore::SharedFile& file : shared.files) {
            const std::filesystem::path target = folder / file.name;
            std::filesystem::create_directories(target.parent_path());
            written.push_back(target);
            write_file_atomic(target.string(), file.text.data(), file.text.size());
        }
        written.push_back(scene);
        write_file_atomic(scene.string(), shared.scene_text.data(), shared.scene_text.size());
        LoadContext context = LoadContext::trusted();
        context.folder = folder.string();  // the messages name the scene "shared-scene.json"
        load_scene_file(scene.filename().string(), context);
    } catch (const std::exception& e) {
        result = text::one_line(e.what());
        std::error_code ec;
        for (const std::filesystem::path& file : written) std::filesystem::remove(file, ec);
    }
    return result.c_str();
}

// Practice mode against the assignment file `path` (picked files, already in
// the work folder: its reference and start scenes beside it), as
// ?assignment= starts it: the start scene becomes the scene, a fresh history,
// the live grade. "" or the one-line reason (the scene stays then).
EMSCRIPTEN_KEEPALIVE const char* m3055_practise(const char* path) {
    static std::string result;
    result.clear();
    ExplorerSession* s = web::session();
    if (!s) return result.assign("m3055: the explorer did not start").c_str();
    explore::Explorer& explorer = s->explorer();
    try {
        grading::load_assignment(path);  // a bad file changes nothing
        grading::Assignment assignment = explore::open_assignment(explorer, path, false);
        explore::start_history(explorer);
        if (!s->practise(std::move(assignment))) result = text::one_line(explorer.session.messages.error);
    } catch (const std::exception& e) {
        result = text::one_line(e.what());
    }
    explorer.session.render_needed = true;
    return result.c_str();
}

// The CPU time of each frame that rendered a changed scene so far, as a JSON
// array of milliseconds (m3055.frameTimes(); scripts/bench-web).
EMSCRIPTEN_KEEPALIVE const char* m3055_render_frame_ms(void) {
    static std::string result;
    result = "[";
    if (ExplorerSession* s = web::session())
        for (double ms : s->render_frame_ms()) result += (result.size() > 1 ? "," : "") + std::to_string(ms);
    result += "]";
    return result.c_str();
}

// 1 when the explorer has nothing left to do until the next input (every
// queued event handled, its frames drawn: ExplorerSession::idle), else 0.
EMSCRIPTEN_KEEPALIVE int m3055_idle(void) {
    ExplorerSession* s = web::session();
    return s && s->idle() ? 1 : 0;
}

// 1 when the scene has edits since it was loaded or saved (the desktop asks
// before quitting then; the page asks before it is closed or reloaded), else 0.
EMSCRIPTEN_KEEPALIVE int m3055_unsaved(void) {
    ExplorerSession* s = web::session();
    return s && explore::work_unsaved(s->explorer()) ? 1 : 0;
}

// The practice grade line as `m3055 grade` scores it ("" outside practice mode).
EMSCRIPTEN_KEEPALIVE const char* m3055_grade_line(void) {
    static std::string result;
    ExplorerSession* s = web::session();
    result = s ? s->grade_now() : "";
    return result.c_str();
}

}  // extern "C"
