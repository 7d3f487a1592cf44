// report.html's 3D view: three.js's classic builds copied next to the page, the glTF
// embedded, and a small script that frames the room, lights it and lets the client
// turn it.
#include <luxplan/output/report_viewer.h>

#include <cstdlib>
#include <fstream>
#include <iterator>
#include <vector>

#include <luxplan/core/atomic_file.h>
#include <luxplan/core/error.h>

namespace tinygltf {
// Exported by Debian's libtinygltf (declared only in its implementation part).
std::string base64_encode(unsigned char const* bytes, unsigned int length);
}  // namespace tinygltf

namespace luxplan {
namespace {

#ifndef LUXPLAN_WEB_DIR
#define LUXPLAN_WEB_DIR "web/node_modules/three"
#endif

// Package file -> report file.
constexpr const char* kPackageFiles[][2] = {{"build/three.min.js", "viewer/three.min.js"},
                                            {"examples/js/loaders/GLTFLoader.js", "viewer/GLTFLoader.js"},
                                            {"examples/js/controls/OrbitControls.js", "viewer/OrbitControls.js"}};

std::string readAll(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) throw IoError("cannot read " + file.string());
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// Frames the room from the first glTF camera or from above a corner of the room's
// bounds (the scene's extras.room; without one, of the whole model);
// the file's lights are photometric (tens of klx of sun, lamps in candela), far beyond
// a screen's range, so the view lights the room with a hemisphere light and a
// directional light along the file's sun (if any) instead.
constexpr const char* kViewerScript = R"js(
(function () {
  const body = document.body;
  window.addEventListener('error', (e) => { body.dataset.viewerError = String(e.message || e); });
  try {
    const canvas = document.getElementById('viewer-canvas');
    const renderer = new THREE.WebGLRenderer({ canvas, antialias: true, preserveDrawingBuffer: true });
    renderer.setPixelRatio(window.devicePixelRatio || 1);
    renderer.setSize(canvas.clientWidth || 800, canvas.clientHeight || 500, false);
    renderer.outputEncoding = THREE.sRGBEncoding;
    const scene = new THREE.Scene();
    scene.background = new THREE.Color(0xf4f4f0);
    const camera = new THREE.PerspectiveCamera(55, (canvas.clientWidth || 800) / (canvas.clientHeight || 500), 0.05, 500);
    const controls = new THREE.OrbitControls(camera, canvas);
    const glb = Uint8Array.from(atob(document.getElementById('viewer-glb').textContent.trim()), (c) => c.charCodeAt(0));
    new THREE.GLTFLoader().parse(glb.buffer, '', (gltf) => {
      let sun = null;
      gltf.scene.traverse((o) => {
        if (o.isDirectionalLight && o.name.startsWith('sun')) sun = o;
        if (o.isLight) o.visible = false;
        if (o.isMesh && o.material && o.material.emissive) o.material.emissiveIntensity = 1;
      });
      scene.add(gltf.scene);
      scene.add(new THREE.HemisphereLight(0xffffff, 0x888880, 0.9));
      const key = new THREE.DirectionalLight(0xffffff, 0.6);
      if (sun) {
        sun.updateMatrixWorld();
        const dir = new THREE.Vector3(0, 0, -1).transformDirection(sun.matrixWorld);
        key.position.copy(dir.multiplyScalar(-10));
      } else {
        key.position.set(3, 10, 5);
      }
      scene.add(key);
      // Frame the room (the scene's extras.room), not everything around it: from the
      // file's first camera (writeGlb gives every file one, inside the room) turning
      // about the point of its view nearest the room's centre; else from above a
      // corner of the room's bounds (of everything's without a room).
      gltf.scene.updateMatrixWorld(true);
      const all = new THREE.Box3().setFromObject(gltf.scene);
      const json = gltf.parser && gltf.parser.json ? gltf.parser.json : {};
      const sceneDef = (json.scenes || [])[json.scene || 0] || {};
      const roomDef = sceneDef.extras && sceneDef.extras.room;
      const room = roomDef && roomDef.min && roomDef.max
        ? new THREE.Box3(new THREE.Vector3().fromArray(roomDef.min), new THREE.Vector3().fromArray(roomDef.max))
        : all;
      const centre = room.getCenter(new THREE.Vector3()), size = room.getSize(new THREE.Vector3());
      camera.far = Math.max(500, 4 * all.getSize(new THREE.Vector3()).length());
      const first = gltf.cameras && gltf.cameras[0];
      if (first) {
        camera.position.setFromMatrixPosition(first.matrixWorld);
        if (first.isPerspectiveCamera && first.fov > 0) camera.fov = first.fov;
        const ahead = new THREE.Vector3(0, 0, -1).transformDirection(first.matrixWorld);
        const along = Math.max(centre.clone().sub(camera.position).dot(ahead), 0.5);
        controls.target.copy(camera.position).add(ahead.multiplyScalar(along));
      } else {
        const reach = Math.max(size.x, size.y, size.z);
        camera.position.set(centre.x - 0.9 * reach, centre.y + 1.1 * reach, centre.z + 1.1 * reach);
        controls.target.copy(centre);
      }
      camera.updateProjectionMatrix();
      // The node's name as the file gives it (three.js sanitizes object names).
      body.dataset.viewerView = first ? 'camera ' + ((first.userData && first.userData.name) || first.name || '0') : 'room bounds';
      controls.update();
      const draw = () => renderer.render(scene, camera);
      controls.addEventListener('change', draw);
      draw();
      // What was drawn: the share of pixels that are not the background.
      const gl = renderer.getContext(), w = gl.drawingBufferWidth, h = gl.drawingBufferHeight;
      const px = new Uint8Array(4 * w * h);
      gl.readPixels(0, 0, w, h, gl.RGBA, gl.UNSIGNED_BYTE, px);
      let lit = 0;
      for (let i = 0; i < px.length; i += 4)
        if (Math.abs(px[i] - 244) + Math.abs(px[i + 1] - 244) + Math.abs(px[i + 2] - 240) > 12) ++lit;
      body.dataset.viewerLit = (lit / (w * h)).toFixed(3);
      body.dataset.viewer = 'drawn';
    }, (error) => { body.dataset.viewerError = 'glTF: ' + (error && error.message ? error.message : error); });
  } catch (e) {
    body.dataset.viewerError = String(e && e.message ? e.message : e);
  }
})();
)js";

}  // namespace

std::filesystem::path viewerPackageDir() {
    if (const char* dir = std::getenv("LUXPLAN_WEB_DIR"); dir && *dir) return dir;
    return LUXPLAN_WEB_DIR;
}

std::string copyViewerScripts(const std::filesystem::path& folder) {
    const std::filesystem::path package = viewerPackageDir();
    for (const auto& [from, to] : kPackageFiles) {
        std::error_code ec;
        if (!std::filesystem::is_regular_file(package / from, ec))
            return "the 3D viewer's " + (package / from).string() +
                   " is missing (run scripts/install-deps.sh, or set LUXPLAN_WEB_DIR to three.js's npm package)";
    }
    std::error_code ec;
    std::filesystem::create_directories(folder / "viewer", ec);
    if (ec) throw IoError("cannot create " + (folder / "viewer").string() + ": " + ec.message());
    for (const auto& [from, to] : kPackageFiles) writeFileAtomically(folder / to, readAll(package / from));
    return "";
}

std::string viewerSection(const std::filesystem::path& folder) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(folder / "scene.glb", ec)) return "";
    for (const char* script : kViewerScripts)
        if (!std::filesystem::is_regular_file(folder / script, ec)) return "";
    const std::string glb = readAll(folder / "scene.glb");
    std::string html = "<h2>The room in 3D</h2>\n<p class=\"muted\">scene.glb: drag to turn, scroll to zoom, right-drag to pan.</p>\n"
                       "<canvas id=\"viewer-canvas\" style=\"width: 100%; max-width: 960px; height: 540px; "
                       "border: 1px solid #ddd; display: block\"></canvas>\n";
    for (const char* script : kViewerScripts) {
        html += "<script src=\"";
        html += script;
        html += "\"></script>\n";
    }
    html += "<script type=\"application/octet-stream\" id=\"viewer-glb\">\n";
    html += tinygltf::base64_encode(reinterpret_cast<const unsigned char*>(glb.data()), unsigned(glb.size()));
    html += "\n</script>\n<script>";
    html += kViewerScript;
    html += "</script>\n";
    return html;
}

}  // namespace luxplan
