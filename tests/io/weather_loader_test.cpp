// The daylight object's weather file and occupancy as the scene loader reads them: the
// site from the file's LOCATION, the rules that tie them to the sky model, and every
// error with its JSON path.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include <luxplan/io/scene_loader.h>
#include "support/load_problems.h"
#include "support/temp_files.h"
#include "support/test_data.h"

namespace luxplan {
namespace weather_loader {

using nlohmann::json;

// A small room lit by Chicago's year; tests change one thing at a time.
json weatherScene() {
    json s = json::parse(R"({
      "luxplan": 1, "name": "t",
      "materials": {"wall": {"type": "diffuse", "reflectance": 0.6},
                    "glass": {"type": "glass", "transmittance": 0.8}},
      "geometry": [{"name": "room", "room": {"min": [0,0,0], "max": [6,4,3]},
                    "materials": {"floor": "wall", "walls": "wall", "ceiling": "wall"},
                    "openings": [{"wall": "south", "offset": 1.5, "width": 2.0, "sill": 0.9, "height": 1.5, "material": "glass"}]}],
      "samplers": [{"name": "floor", "type": "planar", "center": [3,2,0.8], "size": [2,2], "target": [300,500]}],
      "daylight": {"sky": {"model": "perez"}}
    })");
    s["daylight"]["weather"] = test::kChicagoEpw;
    return s;
}

Scene load(const json& scene, const test::TempDir& dir) { return io::loadScene(dir.write("scene.json", scene.dump(2))); }

TEST(WeatherKey, FileRelativeToTheSceneGivesTheSite) {
    test::TempDir dir;
    std::filesystem::create_directories(dir.path() / "weather");
    std::filesystem::copy_file(test::kChicagoEpw, dir.path() / "weather" / "chicago.epw");
    json s = weatherScene();
    s["daylight"]["weather"] = "weather/chicago.epw";
    Scene scene = load(s, dir);
    ASSERT_TRUE(scene.daylight.has_value());
    ASSERT_TRUE(scene.daylight->weather);
    EXPECT_EQ(scene.daylight->weather->hours.size(), 8760u);
    EXPECT_EQ(scene.daylight->weather->city, "Chicago Ohare Intl Ap");
    EXPECT_EQ(scene.daylight->model, SkyModelType::Perez);
    EXPECT_DOUBLE_EQ(scene.site.latitudeDeg, 41.98);
    EXPECT_DOUBLE_EQ(scene.site.longitudeDeg, -87.92);
    EXPECT_EQ(scene.site.northDeg, 0);
}

TEST(WeatherKey, SiteMayRepeatTheFile) {
    test::TempDir dir;
    json s = weatherScene();
    // Within 0.1 degree: the scene's own values stand; north_deg is always the scene's.
    s["site"] = {{"latitude", 42.05}, {"longitude", -87.85}, {"north_deg", 30}};
    Scene scene = load(s, dir);
    EXPECT_DOUBLE_EQ(scene.site.latitudeDeg, 42.05);
    EXPECT_DOUBLE_EQ(scene.site.longitudeDeg, -87.85);
    EXPECT_DOUBLE_EQ(scene.site.northDeg, 30);
    // A site with only its north: the rest from the file.
    s["site"] = {{"north_deg", -15}};
    scene = load(s, dir);
    EXPECT_DOUBLE_EQ(scene.site.latitudeDeg, 41.98);
    EXPECT_DOUBLE_EQ(scene.site.longitudeDeg, -87.92);
    EXPECT_DOUBLE_EQ(scene.site.northDeg, -15);
}

TEST(WeatherKey, SiteThatDisagreesNamesBoth) {
    json s = weatherScene();
    s["site"] = {{"latitude", 40.5}, {"longitude", -87.92}};
    EXPECT_EQ(test::onlyProblem(s), "/site/latitude: 40.5 disagrees with chicago.epw's LOCATION latitude 41.98 by more than 0.1 degree");
    s["site"] = {{"latitude", 41.98}, {"longitude", -88.1}};
    EXPECT_EQ(test::onlyProblem(s), "/site/longitude: -88.1 disagrees with chicago.epw's LOCATION longitude -87.92 by more than 0.1 degree");
    s["site"] = {{"latitude", 40}, {"longitude", 0}};
    EXPECT_EQ(test::problems(s).size(), 2u);
}

TEST(WeatherKey, OnlyThePerezSkyUsesIt) {
    json s = weatherScene();
    s["daylight"]["sky"] = {{"model", "cie_overcast"}, {"horizontal_illuminance_lx", 10000}};
    s["daylight"]["sun"] = false;
    EXPECT_EQ(test::onlyProblem(s),
              "/daylight/weather: a weather file gives the hours of the \"perez\" sky; sky model \"cie_overcast\" does not use it");
    s = weatherScene();
    s["daylight"].erase("weather");
    EXPECT_EQ(test::onlyProblem(s), "/daylight/sky/model: sky model \"perez\" needs \"weather\" (an EPW file): it builds each hour's sky from the file");
    s = weatherScene();
    s["daylight"]["step_minutes"] = 30;
    EXPECT_EQ(test::onlyProblem(s), "/daylight/step_minutes: \"step_minutes\" does not apply with a weather file (its hours are the time steps)");
}

TEST(WeatherKey, PeriodOfTheYear) {
    test::TempDir dir;
    json s = weatherScene();
    // The year ignored: November to February wraps over New Year (120 days); a whole year.
    s["daylight"]["from"] = "2026-11-01T00:00-06:00";
    s["daylight"]["to"] = "2026-02-28T23:59-06:00";
    Scene scene = load(s, dir);
    EXPECT_EQ(weatherHoursIn(*scene.daylight->weather, scene.daylight->from, scene.daylight->to).size(),
              size_t(30 + 31 + 31 + 28) * 24);
    s["daylight"]["from"] = "2026-01-01T00:00-06:00";
    s["daylight"]["to"] = "2026-12-31T23:59-06:00";
    EXPECT_NO_THROW(load(s, dir));
}

TEST(WeatherKey, BadFilesKeepTheirLine) {
    test::TempDir dir;
    json s = weatherScene();
    s["daylight"]["weather"] = "none.epw";
    EXPECT_EQ(test::loadProblems(s.dump(), dir),
              std::vector<std::string>{"/daylight/weather: " + (dir.path() / "none.epw").string() + ": no such file"});
    dir.write("bad.epw", "LOCATION,Chicago,IL,USA,TMY3,725300,41.98\n");
    s["daylight"]["weather"] = "bad.epw";
    EXPECT_EQ(test::loadProblems(s.dump(), dir),
              std::vector<std::string>{"/daylight/weather: " + (dir.path() / "bad.epw").string() +
                                       ":1: LOCATION has 7 fields, expected 10 (LOCATION,city,state,country,source,WMO,"
                                       "latitude,longitude,time zone,elevation)"});
    s["daylight"]["weather"] = 3;
    EXPECT_EQ(test::onlyProblem(s), "/daylight/weather: expected a string, got a number");
}

TEST(OccupiedKey, Reads) {
    test::TempDir dir;
    json s = weatherScene();
    s["daylight"]["occupied"] = {{"hours", {8, 18}}, {"weekdays", {1, 2, 3, 4, 5}}};
    Scene scene = load(s, dir);
    EXPECT_EQ(scene.daylight->occupied.hours[0], 8);
    EXPECT_EQ(scene.daylight->occupied.hours[1], 18);
    EXPECT_EQ(scene.daylight->occupied.weekdays, (std::vector<int>{1, 2, 3, 4, 5}));
    // Each key optional: the default is every hour of every day.
    s["daylight"]["occupied"] = {{"weekdays", {6, 7}}};
    scene = load(s, dir);
    EXPECT_EQ(scene.daylight->occupied.hours[0], 0);
    EXPECT_EQ(scene.daylight->occupied.hours[1], 24);
    EXPECT_EQ(scene.daylight->occupied.weekdays, (std::vector<int>{6, 7}));
    s["daylight"].erase("occupied");
    scene = load(s, dir);
    EXPECT_EQ(scene.daylight->occupied.weekdays, (std::vector<int>{1, 2, 3, 4, 5, 6, 7}));
}

TEST(OccupiedKey, Errors) {
    json s = weatherScene();
    auto with = [&](const json& occupied) {
        s["daylight"]["occupied"] = occupied;
        return test::onlyProblem(s);
    };
    EXPECT_EQ(with({{"hours", {18, 8}}}),
              "/daylight/occupied/hours: the first hour 18 must come before the second 8 (hours of one day, e.g. [8, 18])");
    EXPECT_EQ(with({{"hours", {8, 8}}}),
              "/daylight/occupied/hours: the first hour 8 must come before the second 8 (hours of one day, e.g. [8, 18])");
    EXPECT_EQ(with({{"hours", {8, 25}}}), "/daylight/occupied/hours/1: value 25 outside [0, 24] h");
    EXPECT_EQ(with({{"hours", {8}}}), "/daylight/occupied/hours: expected an array of 2 numbers, got an array of 1");
    EXPECT_EQ(with({{"weekdays", json::array()}}), "/daylight/occupied/weekdays: no weekday: name at least one (1 = Monday .. 7 = Sunday)");
    EXPECT_EQ(with({{"weekdays", {1, 2, 2}}}), "/daylight/occupied/weekdays/2: weekday 2 repeated");
    EXPECT_EQ(with({{"weekdays", {0, 1}}}), "/daylight/occupied/weekdays/0: expected a weekday 1 (Monday) .. 7 (Sunday), got 0");
    EXPECT_EQ(with({{"weekdays", {1.5}}}), "/daylight/occupied/weekdays/0: expected a weekday 1 (Monday) .. 7 (Sunday), got 1.5");
    EXPECT_EQ(with({{"weekdays", {"Monday"}}}),
              "/daylight/occupied/weekdays/0: expected a weekday 1 (Monday) .. 7 (Sunday), got a string");
    EXPECT_EQ(with({{"days", {1}}}).rfind("/daylight/occupied/days: unknown key", 0), 0u) << with({{"days", {1}}});
    EXPECT_EQ(with(8), "/daylight/occupied: expected an object, got a number");
}

}  // namespace weather_loader
}  // namespace luxplan
