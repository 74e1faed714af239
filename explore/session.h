// The session: what the running explorer keeps besides the document and the
// view. Its messages, where files go, the .brdf files it watches and the work
// waiting for a frame, and what the platform (the desktop window or a browser
// page) offers. Nothing here is saved or undone.
#pragma once

#include "explore/light_plan.h"
#include "explore/practice_status.h"
#include "models/material.h"

#include <cstdint>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace m3055::explore {

struct Messages {
    std::string status;  // the last action (saved ..., loaded ..., undid ...)
    std::string error;   // the last error, shown in red until the next one clears it
    std::string load_error;  // the last failed load, beside the Load control and in its dialog
    // The last .brdf parse or GLSL error (the Material section, in the file's own lines) and its file.
    std::string brdf_error, brdf_path;
};

// Where files are saved and screenshots written.
struct FilePlaces {
    std::string save_name = "m3055-scene.json";  // Save As's proposal for a scene without a file (practice: submission.json)
    std::string save_dir;            // the folder of the last scene file loaded or saved: Save As proposes it
    std::string screenshot_dir = ".";  // F12: the next free NAME-0001.png in this folder
    std::string overwrite_warned;    // Save As: the existing file the user was warned about (a second Save writes it)
    bool quit_after_save = false;    // the unsaved-edits dialog's Save went to Save As
};

// The .brdf files in use, polled for changes (explore/brdf_files.h).
struct BrdfWatch {
    std::map<std::string, std::string> stamps;  // each file's "mtime size"
    double next_poll = 0.0;
    // Changed files found by the last poll, reloaded by the next one (after a
    // frame has shown "reloading FILE...": explore/busy.h).
    std::vector<std::string> reload_pending;
    // The files in use, found again only when the document's revision changes
    // (a frame must not look through 100 000 materials).
    std::vector<std::string> in_use;
    std::uint64_t in_use_revision = ~std::uint64_t(0);
};

// Where the explorer runs. In a browser page (app/web/) nothing quits the
// page, a file the explorer writes (a saved scene, a screenshot) is also
// offered as a download, and File > Open is the browser's file chooser: the
// page sets these; the desktop window leaves them as they are.
// The modifiers that, with a digit, load a figure preset (explore/keys.h).
// In a browser Ctrl+1...9 switch tabs and Ctrl+0 resets the zoom, so the page
// takes Ctrl+Alt+digit, as web editors do for their own number shortcuts.
enum class FigureChord { ctrl, ctrl_alt };

struct Platform {
    bool can_quit = true;
    FigureChord figure_chord = FigureChord::ctrl;
    std::function<void(const std::string& path)> file_written;
    std::function<void()> pick_file;
    // Where saved files name a .brdf by a relative path: the page's work
    // folder, whose files leave as downloads side by side. "" (the desktop): absolute paths.
    std::string brdf_paths_relative_to;
    // Whether a file name was already handed out, outside the folders (the
    // page: a download of an earlier visit): the next screenshot skips it.
    std::function<bool(const std::string& name)> name_taken;
    // The platform shows the current error in a place of its own (the page's
    // bar: explore/current_error.h); the side panel then has no error block.
    bool error_line_outside = false;
    // The .brdf files in use are re-read when they change on disk; a page's
    // change only when picked again (Open...), which reloads them itself.
    bool watch_files = true;
    // The GLSL check of a (re)loaded .brdf material: a GL compile by the
    // frame loop's context ("" when it compiles, or when there is no context).
    std::function<std::string(const Material&)> brdf_compile_check;
};

struct Session {
    Messages messages;
    FilePlaces files;
    BrdfWatch brdf_watch;
    LightPlanReadouts light_plan;  // the Lights panel's plot: subject and key-to-fill (explore/light_plan.h)
    Platform platform;
    PracticeStatus practice;  // --assignment: the live grade (explore/practice.h)
    std::string busy;         // this frame's busy_line (explore/busy.h), beside the menu
    bool render_needed = true;  // the document or the view changed: the displays are drawn again once
    bool quit = false;          // the frame loop ends
    // A document with unsaved edits that a load or a preset replaced, as
    // saved_key names it (its file, or "\n" + its name; "" for none): undo
    // brings it back, so quitting asks first (explore/explorer.h: work_unsaved).
    std::string replaced_unsaved;
};

}  // namespace m3055::explore
