// The 3D view of report.html: three.js (from the npm registry, installed by
// scripts/install-deps.sh into web/node_modules) copied into the report folder as
// classic scripts, and scene.glb embedded in the page, so that the page draws the room
// offline and from file:// (where browsers refuse module scripts and fetches).
#pragma once

#include <filesystem>
#include <string>

namespace luxplan {

// The folder holding three.js's package (build/three.min.js, examples/js/...):
// $LUXPLAN_WEB_DIR if set, else where the set-up installs it.
std::filesystem::path viewerPackageDir();

// The viewer's scripts, relative to the report folder, in load order.
inline constexpr const char* kViewerScripts[] = {"viewer/three.min.js", "viewer/GLTFLoader.js", "viewer/OrbitControls.js"};

// Copies the viewer's scripts into folder/viewer/. Returns "" on success, else why
// not (the package is missing: run scripts/install-deps.sh); throws IoError when a
// file cannot be written.
std::string copyViewerScripts(const std::filesystem::path& folder);

// The page's 3D section for folder/scene.glb: a canvas, the scripts, the glTF as
// base64 and the code that draws it with orbit controls. When it has drawn, the page's
// <body> gets data-viewer="drawn", data-viewer-lit="F" (the share of canvas pixels
// that are not the background) and data-viewer-view (where the view starts: "camera
// NAME", the file's first camera, or "room bounds"); a script error sets
// data-viewer-error. "" when
// scene.glb or the scripts are not in the folder.
std::string viewerSection(const std::filesystem::path& folder);

}  // namespace luxplan
