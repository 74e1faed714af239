// The explorer as a web page (scripts/web): the desktop explorer's session
// (app/explore_ui/explore.h) on a WebGL2 canvas, driven by the browser's
// animation frames instead of a blocking loop. page.js starts it with
// arguments: --assignment PATH (practice mode, the assignment's files already
// fetched into the work folder), --script PATH (?script=: UI actions one a
// frame, explore/script.h) and/or a scene path (a share link's scene).
#include "app/web/page.h"
#include "explore/files.h"
#include "explore/brdf_files.h"
#include "explore/current_error.h"
#include "explore/explorer.h"

#include <emscripten.h>
#include <emscripten/html5.h>

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <string>

namespace {

using namespace m3055;

// A written file leaves the page as a download (the browser's "save").
EM_JS(void, offer_download, (const char* path), { window.m3055Page.download(UTF8ToString(path)); });
// File > Open: the browser's file chooser (page.js loads what is picked).
EM_JS(void, open_file_chooser, (), { window.m3055Page.chooseFile(); });
// The page shows why the explorer could not start.
EM_JS(void, report_start_failure, (), { window.m3055Page.startFailed(); });
// The page's window.m3055.ready resolves.
EM_JS(void, report_started, (), { window.m3055Page.started(); });

// A frame that rendered a changed scene: page.js notes input-to-pixels latency.
EM_JS(void, report_rendered, (), { window.m3055Page.rendered(); });
// The loop sleeps: page.js wakes it on the next input, or after `ms` (>= 0).
EM_JS(void, report_sleeping, (double ms), { window.m3055Page.sleeping(ms); });
// The explorer's current error changed: the page's bar shows it ("": none).
EM_JS(void, report_error, (const char* text), { window.m3055Page.explorerError(UTF8ToString(text)); });
// A name this page has downloaded before, in this visit or an earlier one.
EM_JS(int, downloaded_before, (const char* name), { return window.m3055Page.downloadedBefore(UTF8ToString(name)) ? 1 : 0; });

bool g_sleeping = false;
explore::CurrentError g_error;

// One animation frame. Left alone the explorer draws nothing (as the desktop
// waits for an event): the animation frames stop until page.js wakes them.
void frame(void*) {
    ExplorerSession* s = web::session();
    if (!s) return;
    const long before = s->renders();
    s->step();  // the page never ends: nothing quits it
    if (s->renders() != before) report_rendered();
    if (g_error.update(s->explorer().session.messages)) report_error(g_error.text().c_str());
    const double sleep = s->asked_sleep();
    if (sleep == 0.0) return;
    emscripten_pause_main_loop();
    g_sleeping = true;
    report_sleeping(sleep < 0.0 ? -1.0 : sleep * 1000.0);
}

}  // namespace

// Input, a call of the page's API, or a timed job's time: the animation frames go on.
extern "C" EMSCRIPTEN_KEEPALIVE void m3055_wake(void) {
    if (!g_sleeping) return;
    g_sleeping = false;
    emscripten_resume_main_loop();
}

int main(int argc, char** argv) {
    std::error_code ec;
    std::filesystem::create_directories(web::kWorkFolder, ec);
    std::filesystem::current_path(web::kWorkFolder, ec);

    ExploreOptions options;
    for (int i = 1; i < argc; ++i) {
        if (std::strcmp(argv[i], "--assignment") == 0 && i + 1 < argc) options.assignment_path = argv[++i];
        else if (std::strcmp(argv[i], "--script") == 0 && i + 1 < argc) options.script_path = argv[++i];
        else options.scene_path = argv[i];
    }
    // The canvas as page.js sized it: the page's area in device pixels, so
    // that a whole-pixel magnification stays sharp on a HiDPI screen.
    int canvas_w = 0, canvas_h = 0;
    emscripten_get_canvas_element_size("#canvas", &canvas_w, &canvas_h);
    options.window_width = canvas_w > 0 ? canvas_w : 1280;
    options.window_height = canvas_h > 0 ? canvas_h : 720;

    auto session = ExplorerSession::open(options, [](explore::Explorer& explorer) {
        explore::Platform& platform = explorer.session.platform;
        platform.can_quit = false;
        platform.figure_chord = explore::FigureChord::ctrl_alt;  // Ctrl+digit is the browser's
        platform.file_written = [](const std::string& path) { offer_download(path.c_str()); };
        platform.pick_file = [] { open_file_chooser(); };
        platform.brdf_paths_relative_to = web::kWorkFolder;  // the names the user's files had
        platform.watch_files = false;  // a page cannot see the user's disk: a changed file is picked again
        platform.error_line_outside = true;  // the bar shows the current error
        // Screenshots go on numbering after those downloaded in earlier visits.
        platform.name_taken = [](const std::string& name) { return downloaded_before(name.c_str()) != 0; };
        explorer.session.files.screenshot_dir = "screenshots";  // downloaded as they are taken
        std::filesystem::create_directories(explorer.session.files.screenshot_dir);
    });
    if (!session) {
        report_start_failure();
        return 1;
    }
    web::set_session(std::move(session));
    emscripten_set_main_loop_arg(frame, nullptr, 0, false);
    report_started();
    return 0;
}
