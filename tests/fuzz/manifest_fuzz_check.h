// What the fuzzer checks on a batch manifest, and the dispatch
// between the two kinds of input one libFuzzer target takes:
//     #manifest
//     [{"scene": "a.json", "out": "a.png"}, ...]
// is a manifest; anything else is a scene with optional `--set` lines
// (scene_fuzz_check.h). The loader must give a list of entries or a
// ManifestError with one line of valid UTF-8 naming the manifest, never
// another exception, a crash or a hang; the entries' files are then checked
// together (io/run_files.h), which must not throw either. Header-only, like
// scene_fuzz_check.h, so tests/fuzz_regressions_test.cpp re-checks the inputs.
#pragma once

#include "scene_fuzz_check.h"
#include "scene/manifest.h"
#include "io/message_text.h"
#include "io/run_files.h"

#include <cstddef>
#include <cstdint>
#include <string>

namespace m3055::fuzz {

inline constexpr const char* kManifestMarker = "#manifest\n";
// A folder that does not exist: relative entries resolve nowhere, so checking
// them touches nothing on disk.
inline constexpr const char* kManifestSource = "/nonexistent-m3055-fuzz/m.json";

// "" when the message is one line of valid UTF-8 without control characters.
inline std::string check_message_text(const std::string& message) {
    if (!text::is_valid_utf8(message)) return "error message is not valid UTF-8: " + text::escape(message);
    for (const unsigned char c : message)
        if (c < 0x20 || c == 0x7F) return "error message holds a control character: " + text::escape(message);
    return "";
}

inline std::string check_manifest_text(const std::string& manifest) {
    std::vector<BatchItem> items;
    try {
        items = parse_manifest(manifest, kManifestSource);
    } catch (const ManifestError& error) {
        const std::string message = error.what();
        if (message.rfind(std::string(kManifestSource) + ": ", 0) != 0)
            return "manifest error does not name the manifest: " + text::escape(message);
        return check_message_text(message);
    } catch (const std::exception& error) {
        return std::string("manifest loader threw a non-ManifestError: ") + error.what();
    }
    try {
        io::RunFiles files;
        for (std::size_t i = 0; i < items.size(); ++i) {
            if (items[i].scene.find('\0') != std::string::npos || items[i].out.find('\0') != std::string::npos ||
                items[i].raw.find('\0') != std::string::npos)
                return "a path with a NUL character was accepted";
            files.add_input(i, "[i].scene", items[i].scene);
            files.add_output(i, "[i].out", items[i].out);
            if (!items[i].raw.empty()) files.add_output(i, "[i].raw", items[i].raw);
        }
        for (const auto& [owner, problem] : files.check())
            if (std::string bad = check_message_text(problem); !bad.empty()) return bad;
    } catch (const std::exception& error) {
        return std::string("checking the entries' files threw: ") + error.what();
    }
    return "";
}

// The fuzz target's and the regression test's entry point.
inline std::string check_fuzz_input(const std::uint8_t* data, std::size_t size) {
    const std::string marker = kManifestMarker;
    if (size >= marker.size() && std::string(reinterpret_cast<const char*>(data), marker.size()) == marker)
        return check_manifest_text(std::string(reinterpret_cast<const char*>(data) + marker.size(), size - marker.size()));
    return check_scene_input(data, size);
}

}  // namespace m3055::fuzz
