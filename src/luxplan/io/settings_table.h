// The one key table of the run's settings (scene/settings.h): each row a key, its type
// and range or choices, its default, the commands that read it, a line of doc and its
// reader. The scene file's "optimizer" object is read through it, `--set KEY=VALUE` is
// that object's key given on the command line, and `luxplan settings`, `--help-all`
// and docs/scene-format.md's table list it (a test keeps the doc in step).
#pragma once

#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include <luxplan/json/fields.h>
#include <luxplan/scene/settings.h>

namespace luxplan::io {

// How a row reads its key into the settings and writes it back as the file would hold it.
struct SettingAccess {
    // Reads the key from the object (when present) into the settings, reporting a bad
    // value through the object; rows run in table order (a count's default may follow
    // an earlier key's value).
    std::function<void(const json::Fields&, OptimizerSettings&)> read;
    // The key's value in the settings (null: an optional left to the command's default).
    std::function<json::Json(const OptimizerSettings&)> write;
};

struct SettingKey {
    const char* key;
    const char* type;      // "whole number", "number", "true or false", the choices ("on, off") ...
    std::string range;     // the values allowed, as the docs say them ("" where the type says it)
    const char* fallback;  // the default, per command where they differ
    const char* commands;  // the commands that read it
    const char* doc;       // one line
    SettingAccess access;
};

// Every key, in the order the object is read.
const std::vector<SettingKey>& settingKeys();

// Reads the "optimizer" object through the table, then the keys that exclude each other.
void readSettings(const json::Fields& f, OptimizerSettings& s);

// Every key's value in these settings as the scene file's "optimizer" object would
// hold it (an optional left to the command's default is absent): read back through
// readSettings it gives the same settings (report.json's "settings").
json::Json settingsJson(const OptimizerSettings& s);

// One `--set KEY=VALUE`: the value as the scene file would hold it (true/false, a
// number, a JSON object, else a string).
struct SettingOverride {
    std::string key;
    json::Json value;
};
// Parses "KEY=VALUE"; throws std::invalid_argument with the reason (no "=", no key, an
// unknown key with the nearest known ones).
SettingOverride parseSetting(const std::string& text);
// Every problem of these settings read alone, as "--set KEY=VALUE: message" lines
// (empty: none): a value of the wrong type or out of range, keys that exclude each other.
std::vector<std::string> settingProblems(const std::vector<SettingOverride>& settings);
// The table as text: each key with its type, default, commands and doc (`luxplan settings`).
std::string settingsTableText();

}  // namespace luxplan::io
