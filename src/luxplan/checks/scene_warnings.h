// Inputs that load but cannot be what the user meant: `luxplan validate` prints them
// as FILE: /json/path: warning: message and still exits 0. Each check is one file of
// this folder; every warning names the item it is about (its JSON path) and why.
#pragma once

#include <vector>

#include <luxplan/core/error.h>
#include <luxplan/scene/scene.h>

namespace luxplan {

// What the sampler checks share: a sampler's measurement points where `frame` puts it
// (grid points, eye, a volume's corners), and a point as the warnings print it.
std::vector<Vec3> measurementPoints(const LightSamplerSpec& sampler, const Transform& frame);
std::string pointText(const Vec3& p);

// Every check below, in this order. Carried emitters and samplers, and entities, are
// judged where the scene file places them.
std::vector<Diagnostic> sceneWarnings(const Scene& scene);

// An emitter whose light cannot leave: every one of kEnclosureRays directions from it
// (from its centre over the whole sphere; from just in front of a flat one over its
// hemisphere) first meets an opaque surface (not glass, not translucent) of its own
// entity or of an entity it moves with, or, for a fixed luminaire, of static geometry
// other than the room shell (enclosure.cpp).
std::vector<Diagnostic> enclosedEmitters(const Scene& scene);
inline constexpr int kEnclosureRays = 1024;

// A luminaire whose centre, or a sampler's measurement point (its grid points, its
// eye, its volume's corners), outside every room box by more than a millimetre; and a
// sampler with a point on a room's wall, floor or ceiling (within a millimetre, not in
// an opening) that faces out through it, which then measures the light outside
// (outside_room.cpp). Scenes without a room are not judged.
std::vector<Diagnostic> outsideTheRoom(const Scene& scene);

// A sampler's measurement point (as outsideTheRoom takes them) inside a closed opaque
// box without a luminaire, where no light reaches: it reads 0, and the path tracer
// traces no path there (pathtracer/sealed_boxes.h; sealed_samplers.cpp).
std::vector<Diagnostic> sealedSamplers(const Scene& scene);

// A daylight interval at whose steps the sun is below the horizon (Preetham and CIE
// general skies, which are dark then): all of them, or some (dark_daylight.cpp).
std::vector<Diagnostic> darkDaylight(const Scene& scene);

// Movable entities whose scene placement passes a hard limit: in a wall, a static
// item or a blocker, or with a footprint outside the room or its footprint region
// (start_placement.cpp). Measure and render use that placement; a search starting
// from it (optimizer.start "scene") first repairs it.
std::vector<Diagnostic> startPlacement(const Scene& scene);

// A maintenance factor below kLowestUsualMaintenanceFactor: valid, but darker than any
// usual maintenance schedule leaves a room (maintenance_factor.cpp).
std::vector<Diagnostic> lowMaintenanceFactor(const Scene& scene);
inline constexpr double kLowestUsualMaintenanceFactor = 0.5;

}  // namespace luxplan
