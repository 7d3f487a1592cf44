#!/usr/bin/env python3
"""Every key the scene loader reads appears in docs/scene-format.md, as `key`.

usage: tests/scripts/scene_keys_documented.py [SOURCE_DIR]

The loader reads a scene only through json::Fields (src/luxplan/json/fields.h), in
src/luxplan/io/scene_loader.cpp and in the readers of the kinds it hands objects to
(light samplers, emitter shapes, constraint types), and the `optimizer` object
through the settings' key table (src/luxplan/io/settings_table.cpp, its rows' keys). In each such file this finds the
names that hold a Fields object (`Fields f(...)`, `const Fields& f`, `json::Fields& f`)
and collects the string literals given as keys:
  - to an accessor: f.number("key" ...), f.has("key"), f.get("key"), f.at("key"),
    f.error("key", ...) (an error with one argument is a message, not a key), ...;
  - to a helper that takes the object and a key: readTime(f, "start"), ...;
and, in the loader, the keys it looks up before it builds Fields (`contains("key")`,
`j["key"]`: templates). A key is documented when the document's inline code names it:
`key`, a path ending in it (`optimizer.seed`, `openings[].blind`), or a JSON key in a
snippet (`{"eye": [x,y,z]}`, `{"start", "end"}`). Exit 0 when all are, 1 listing the missing ones
with the file and line that reads each, 2 when the sources cannot be read or the
extraction finds too little to be trusted.
"""
import os
import re
import sys

ACCESSORS = ("number", "integer", "unsignedInteger", "boolean", "string", "vec2", "vec3",
             "color", "direction", "array", "numbers", "has", "get", "at", "missing", "error")
KEY = r'"([a-z][a-z0-9_]*)"'
# Keys every reading must find: if one of these is not extracted, the extraction broke.
EXPECTED = ("luxplan", "materials", "reflectance", "geometry", "entities", "samplers",
            "constraints", "paths_per_point", "target", "center", "shape", "tolerance")


def strip_comments(text):
    text = re.sub(r"/\*.*?\*/", lambda m: "\n" * m.group(0).count("\n"), text, flags=re.S)
    return re.sub(r"//[^\n]*", "", text)


def fields_names(text):
    """Identifiers that hold a json::Fields in this file."""
    names = set(re.findall(r"\bFields\s*&\s*(\w+)", text))            # parameters and references
    names |= set(re.findall(r"\bFields\s+(\w+)\s*[({]", text))        # Fields f(sink, ...)
    return names


def keys_in(path, text, is_loader):
    """(key, line) pairs read from `text`."""
    found = []
    names = fields_names(text)

    def add(match, group=1):
        found.append((match.group(group), text.count("\n", 0, match.start()) + 1))

    if names:
        var = "(?:" + "|".join(sorted(map(re.escape, names))) + ")"
        accessor = "(?:" + "|".join(ACCESSORS) + ")"
        for m in re.finditer(r"\b%s\s*(?:\.|->)\s*(%s)\s*\(\s*%s\s*([,)])" % (var, accessor, KEY), text):
            if m.group(1) == "error" and m.group(3) == ")":
                continue  # f.error("message"): the object's own problem, no key
            add(m, 2)
        # A helper handed the object and a key: readTime(f, "start"), materialRef(f, "material", true).
        for m in re.finditer(r"\b\w+\s*\(\s*%s\s*,\s*%s" % (var, KEY), text):
            add(m)
    if is_loader:
        for m in re.finditer(r"\.contains\(\s*%s\s*\)" % KEY, text):
            add(m)
        for m in re.finditer(r"\[\s*%s\s*\]" % KEY, text):
            add(m)
    return [(k, path, line) for k, line in found]


def table_keys(path, text):
    """The settings' key table (io/settings_table.cpp): a row starts {"key", "type", ...}."""
    return [(m.group(1), path, text.count("\n", 0, m.start()) + 1)
            for m in re.finditer(r'\{\s*%s\s*,\s*"' % KEY, text)]


def documented(doc):
    """The keys the document names in inline code: `key`, a path to it
    (`optimizer.seed`, `openings[].blind`), a JSON key (`{"eye": [x,y,z], ...}`) or a
    list of keys (`{"start", "end"}`). Fenced blocks are examples, not documentation."""
    doc = re.sub(r"^```.*?^```", "", doc, flags=re.S | re.M)
    keys = set()
    for span in re.findall(r"`([^`]+)`", doc):
        if "\n\n" in span:
            continue  # not a span: a stray backtick paired across paragraphs
        span = " ".join(span.split())
        if re.fullmatch(r'"?[A-Za-z_][\w.\[\]]*"?', span):
            keys.update(part for part in re.split(r"[.\[\]\"]+", span) if part)
        keys.update(re.findall(r'"(\w+)"\s*:', span))
        if re.fullmatch(r'\{\s*"\w+"(\s*,\s*"\w+")*\s*\}', span):
            keys.update(re.findall(r'"(\w+)"', span))
    return keys


def main():
    root = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    src = os.path.join(root, "src", "luxplan")
    loader = os.path.join(src, "io", "scene_loader.cpp")
    doc_path = os.path.join(root, "docs", "scene-format.md")
    try:
        with open(doc_path, encoding="utf-8") as f:
            doc = f.read()
        settings = os.path.join(src, "io", "settings_table.cpp")
        files = [loader, settings]
        # The kinds' readers: every file of the registries' modules that reads Fields.
        for module in ("lightsamplers", "emitters", "constraints", "json"):
            folder = os.path.join(src, module)
            for name in sorted(os.listdir(folder)):
                if name.endswith(".cpp") and name != "fields.cpp":
                    files.append(os.path.join(folder, name))
        reads = []
        for path in files:
            with open(path, encoding="utf-8") as f:
                text = strip_comments(f.read())
            reads += keys_in(os.path.relpath(path, root), text, path == loader)
            if path == settings:
                reads += table_keys(os.path.relpath(path, root), text)
    except OSError as e:
        print(f"scene_keys_documented: cannot read {e.filename}: {e.strerror}", file=sys.stderr)
        return 2

    keys = {}
    for key, path, line in reads:
        keys.setdefault(key, (path, line))
    lost = [k for k in EXPECTED if k not in keys]
    if lost or len(keys) < 100:
        print(f"scene_keys_documented: the extraction found {len(keys)} keys and missed "
              f"{', '.join(lost) or 'none of the expected ones'}: the loader's way of reading keys "
              "changed; update tests/scripts/scene_keys_documented.py", file=sys.stderr)
        return 2

    named = documented(doc)
    missing = sorted(k for k in keys if k not in named)
    for k in missing:
        path, line = keys[k]
        print(f"docs/scene-format.md: key `{k}` is not documented (read at {path}:{line})")
    print(f"{len(keys)} scene keys read by the loader, {len(keys) - len(missing)} documented, "
          f"{len(missing)} missing")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
