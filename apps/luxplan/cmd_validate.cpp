// `luxplan validate SCENE` (exit 0, or every problem as FILE: /json/path: message;
// warnings, checks/scene_warnings.h, on stderr either way) and `luxplan info SCENE`
// (a summary of what the scene holds).
#include <iomanip>
#include <iostream>

#include "commands.h"
#include <luxplan/api/scene.h>
#include <luxplan/checks/scene_warnings.h>
#include <luxplan/constraints/constraint_type.h>
#include <luxplan/daylight/weather.h>
#include <luxplan/io/layout_io.h>
#include <luxplan/io/scene_loader.h>
#include <luxplan/emitters/emitter_shape.h>
#include <luxplan/lightsamplers/sampler_type.h>
#include <luxplan/scene/layout.h>

namespace luxplan::cli {
namespace {

std::string entityName(const Scene& s, int e) { return e == kRoomEntity ? "room" : e >= 0 ? s.entities[e].path : "?"; }

void printSummary(const Scene& s, std::ostream& out) {
    out << std::fixed << std::setprecision(2);
    out << "scene \"" << s.name << "\" (" << s.file.string() << ")\n";
    out << "  site: latitude " << s.site.latitudeDeg << ", longitude " << s.site.longitudeDeg << ", north " << s.site.northDeg
        << " deg\n";
    if (s.daylight) {
        const DaylightParams& d = *s.daylight;
        out << "  daylight: " << skyModelNames().name(d.model) << " sky" << (d.sunEnabled() ? " + sun" : "");
        if (d.sunOverride) out << " fixed at altitude " << d.sunOverride->altitudeDeg << ", azimuth " << d.sunOverride->azimuthDeg;
        if (d.weather)  // its hours are the steps; from/to only select them
            out << ", weather " << d.weather->file.filename().string() << " (" << d.weather->city << "): "
                << weatherHoursIn(*d.weather, d.from, d.to).size() << " of its " << d.weather->hours.size() << " hours";
        else if (d.from) out << ", " << d.from->str() << (d.to ? " to " + d.to->str() + " every " + std::to_string(int(d.stepMinutes)) + " min" : "");
        out << "\n";
    } else {
        out << "  daylight: none (artificial light only)\n";
    }
    int rooms = 0, openings = 0, glazed = 0;
    for (const auto& g : s.geometry)
        if (g.room) {
            ++rooms;
            for (const auto& o : g.room->openings) ++openings, glazed += o.material.has_value();
        }
    out << "  materials: " << s.materials.size() << "\n";
    out << "  rooms: " << rooms << ", openings: " << openings << " (" << glazed << " glazed)\n";
    for (const auto& g : s.geometry)
        if (g.room) {
            Vec3 size = g.room->box.size();
            out << "    " << g.name << ": " << size.x << " x " << size.y << " x " << size.z << " m, floor "
                << size.x * size.y << " m2\n";
            for (const auto& o : g.room->openings) {
                out << "      opening on " << wallNames().name(o.wall) << ": ";
                if (o.wall == Wall::Ceiling) out << o.size.x << " x " << o.size.y << " m";
                else out << o.width << " x " << o.height << " m at offset " << o.offset << ", sill " << o.sill;
                out << (o.material ? " glazed (" + s.materials[*o.material].name + ")" : " open") << "\n";
            }
        }
    int blockers = 0;
    for (const auto& g : s.geometry) blockers += g.invisible;
    out << "  static items: " << s.geometry.size() << " (" << blockers << " invisible blockers)\n";
    int fixedLights = 0;
    double flux = 0;
    for (const auto& e : s.emitters) fixedLights += e.entity < 0, flux += e.fluxLm;
    out << "  luminaires: " << fixedLights << " fixed, " << s.emitters.size() - fixedLights << " on entities, "
        << std::setprecision(0) << flux << " lm in all\n" << std::setprecision(2);
    if (s.maintenanceFactor != 1)
        out << "  maintenance factor: " << std::defaultfloat << std::setprecision(6) << s.maintenanceFactor << std::fixed
            << std::setprecision(2) << " (the fluxes below are as new; measured, the luminaires give this share of them)\n";
    for (const auto& e : s.emitters)
        out << "    " << e.name << " (" << e.shape->name() << (e.entity >= 0 ? ", on " + s.entities[e.entity].path : "")
            << "): " << e.shape->describe() << ", " << std::setprecision(0) << e.fluxLm << " lm\n" << std::setprecision(2);
    int groups = 0, movable = 0;
    for (const auto& e : s.entities) groups += e.isGroup(), movable += e.movable();
    out << "  entities: " << s.entities.size() << " (" << groups << " groups, " << movable << " movable)\n";
    for (const auto& e : s.entities) {
        int depth = 0;
        for (int p = e.parent; p >= 0; p = s.entities[p].parent) ++depth;
        out << "    " << std::string(2 * depth, ' ') << e.path << (e.isGroup() ? " [group]" : "");
        if (!e.parts.empty()) {
            out << " parts:";
            for (const auto& p : e.parts) out << " " << p.kind;
        }
        out << (e.movable() ? " regions: " + std::to_string(e.regions.size()) : " fixed");
        if (e.hasGeometry()) out << ", volume " << std::setprecision(3) << e.voxels.volume() << " m3" << std::setprecision(2);
        out << "\n";
    }
    out << "  samplers: " << s.samplers.size() << "\n";
    for (const auto& sp : s.samplers) {
        out << "    " << sp.name << " (" << sp.type->name() << (sp.entity >= 0 ? ", on " + s.entities[sp.entity].path : "")
            << "): " << sp.type->describe() << "; target [" << sp.targetMin << ", " << sp.targetMax << "] "
            << sp.type->unit();
        for (const StatisticGoal& g : sp.statistics)
            out << "; " << statisticNames().name(g.statistic) << " [" << g.targetMin << ", " << g.targetMax << "]";
        out << "\n";
    }
    out << "  constraints: " << s.constraints.size() << "\n";
    for (const auto& c : s.constraints)
        out << "    " << c.kind->name() << " " << entityName(s, c.a) << " - " << entityName(s, c.b) << ": "
            << c.kind->describe() << "\n";
    out << "  overlap rule: tolerance " << s.overlap.tolerance << " of the smaller volume, weight " << s.overlap.weight
        << "; walls, static geometry and blockers at most " << 1e3 * s.overlap.wallTolerance << " l\n";
    out << "  objective: lighting weight " << s.objective.lightingWeight << "; optimizer: " << s.optimizer.iterations
        << " iterations, seed " << s.optimizer.seed << "; paths per point: " << s.optimizer.searchPathsPerPoint
        << " in the search, " << s.optimizer.selectionPathsPerPoint << " for its confirmations and re-measures, "
        << s.optimizer.reportPathsPerPoint << " for the report and measure\n";
}

}  // namespace

void printSceneWarnings(const Scene& scene) {
    for (const std::string& line : api::sceneWarnings(scene)) std::cerr << line << "\n";
}

void registerValidateCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("validate", "Check a scene file against the format; print every error");
    auto scene = std::make_shared<std::string>();
    auto layout = std::make_shared<std::string>();
    cmd->add_option("scene", *scene, "Scene JSON file")->required();
    cmd->add_option("--layout", *layout, "Also check a layout.json against the scene");
    cmd->callback([scene, layout] {
        namingScene(*scene, [&] {
            Scene s = io::loadScene(*scene);
            if (!layout->empty()) io::readLayout(*layout, s);
            printSceneWarnings(s);
        });
        std::cout << *scene << ": valid\n";
    });
}

void registerInfoCommand(CLI::App& app) {
    auto* cmd = app.add_subcommand("info", "Validate a scene and print a summary of it");
    auto scene = std::make_shared<std::string>();
    cmd->add_option("scene", *scene, "Scene JSON file")->required();
    cmd->callback([scene] { namingScene(*scene, [&] { printSummary(io::loadScene(*scene), std::cout); }); });
}

}  // namespace luxplan::cli
