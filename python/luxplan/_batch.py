"""Batches of measure and optimize jobs on a dask.distributed cluster (docs/python.md).

Each job travels with its files: the client reads the scene and every file it names
(meshes and their glTF buffers, photometric files, the weather file) into the task, and
the worker writes them under a folder of its own at their absolute paths (so that a
scene's relative references resolve as on the client), runs the job there, and sends
back the result and the files the job wrote; every staged path in the result is turned
back into the client's. A worker lost mid-job costs a rerun (the scheduler reschedules
the task from its spec, which holds the files); a job that fails comes back as a
JobError in its place.
"""
import hashlib
import json
import os
import shutil
import tempfile
import warnings

__all__ = ["batch", "JobError"]

# The keyword arguments each command takes (Scene.measure's and Scene.optimize's; no
# progress callback: it would run on the worker).
_ARGUMENTS = {
    "measure": {"layout", "paths", "seed", "threads", "at", "annual"},
    "optimize": {"out", "iterations", "seed", "threads", "paths", "pictures", "suggestions", "start", "pdf"},
}
# The scene keys that name a file, relative to the scene's folder or absolute.
_FILE_KEYS = {"mesh", "photometry", "weather"}


class JobError(Exception):
    """A job that failed: its index, scene, command and the error (type and message as
    the engine said them). Returned in the job's place; the batch goes on."""

    def __init__(self, index, scene, command, kind, message, diagnostics=None):
        super().__init__(f"{scene}: {command}: {message}")
        self.index, self.scene, self.command = index, scene, command
        self.kind, self.message, self.diagnostics = kind, message, diagnostics or []


def _referenced(scene_path):
    """The absolute paths of every file the scene names, a glTF's external buffers and
    images too (files that do not exist are left for the loader to refuse)."""
    with open(scene_path, "rb") as f:
        doc = json.loads(f.read())
    folder = os.path.dirname(os.path.abspath(scene_path))
    found = []

    def walk(node):
        if isinstance(node, dict):
            for key, value in node.items():
                if key in _FILE_KEYS and isinstance(value, str):
                    found.append(os.path.normpath(os.path.join(folder, value)))
                else:
                    walk(value)
        elif isinstance(node, list):
            for value in node:
                walk(value)

    walk(doc)
    for path in list(found):
        if path.lower().endswith(".gltf") and os.path.isfile(path):
            try:
                with open(path, "rb") as f:
                    gltf = json.loads(f.read())
            except ValueError:
                continue
            for item in gltf.get("buffers", []) + gltf.get("images", []):
                uri = item.get("uri") if isinstance(item, dict) else None
                if isinstance(uri, str) and not uri.startswith("data:"):
                    found.append(os.path.normpath(os.path.join(os.path.dirname(path), uri)))
    return found


def _bundle(scene, kwargs):
    """The files a job needs: the scene's ({absolute path: bytes}, shared by the jobs of
    one scene), the job's own (a layout or start given as a file), and its kwargs with
    those paths made absolute."""
    files = {}
    for path in [os.path.abspath(scene)] + _referenced(scene):
        if os.path.isfile(path) and path not in files:
            with open(path, "rb") as f:
                files[path] = f.read()
    own = {}
    kwargs = dict(kwargs)
    for key in ("layout", "start"):
        value = kwargs.get(key)
        if value is not None and not isinstance(value, dict):
            path = os.path.abspath(os.fspath(value))
            if os.path.isfile(path):
                with open(path, "rb") as f:
                    own[path] = f.read()
            kwargs[key] = path
    return files, own, kwargs


def _unstaged(value, replacements):
    """`value` with every staged path turned back into the client's."""
    if isinstance(value, str):
        for old, new in replacements:
            value = value.replace(old, new)
        return value
    if isinstance(value, dict):
        return {_unstaged(k, replacements): _unstaged(v, replacements) for k, v in value.items()}
    if isinstance(value, list):
        return [_unstaged(v, replacements) for v in value]
    return value


def _run_job(spec, files):
    """On a worker: the job in a folder of its own, with the scene's `files` and the
    job's own (spec["files"]). ("ok", result, {path in out: bytes})
    or ("error", kind, message, diagnostics)."""
    import luxplan  # the worker's own import

    root = tempfile.mkdtemp(prefix="luxplan-job-")
    staged = os.path.join(root, "files")
    given = spec["scene"]
    given_folder = os.path.dirname(given)
    replacements = [(staged + os.path.dirname(spec["scene_abs"]) + os.sep, given_folder + os.sep if given_folder else ""),
                    (staged + spec["scene_abs"], given), (staged, "")]
    try:
        for path, data in list(files.items()) + list(spec.get("files", {}).items()):
            target = staged + path
            os.makedirs(os.path.dirname(target), exist_ok=True)
            with open(target, "wb") as f:
                f.write(data)
        kwargs = dict(spec["kwargs"])
        for key in ("layout", "start"):
            if isinstance(kwargs.get(key), str):
                kwargs[key] = staged + kwargs[key]
        out = kwargs.pop("out", None)
        if spec["command"] == "optimize" and out is not None:
            kwargs["out"] = os.path.join(root, "out")
        kwargs.setdefault("threads", 1)
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the scene's warnings: the client's Scene says them
            scene = luxplan.Scene(staged + spec["scene_abs"], settings=spec.get("settings"))
            result = getattr(scene, spec["command"])(**kwargs)
        written = {}
        if "out" in kwargs:
            for folder, _, names in os.walk(kwargs["out"]):
                for name in names:
                    path = os.path.join(folder, name)
                    with open(path, "rb") as f:
                        written[os.path.relpath(path, kwargs["out"])] = f.read()
        return ("ok", _unstaged(dict(result), replacements), written)
    except Exception as e:  # noqa: BLE001: every failure of the job is its result
        diagnostics = _unstaged(getattr(e, "diagnostics", []), replacements)
        return ("error", type(e).__name__, _unstaged(str(e), replacements), diagnostics)
    finally:
        shutil.rmtree(root, ignore_errors=True)


def _files(files):
    """A bundle of files as a task of its own: computed again from its spec (which holds
    the bytes) if the worker that holds it is lost."""
    return files


def batch(jobs, client=None, retries=0):
    """Runs `jobs` on a dask.distributed cluster and returns their results in job order.

    Each job is a dict: "command" ("measure" or "optimize"), "scene" (a scene file's
    path), optionally "settings" (as Scene's) and the keyword arguments of Scene.measure
    or Scene.optimize (no progress); "threads" defaults to 1 (one job per worker
    thread). A result is what the call returns (an optimize job with "out" also gets its
    files written there); a job that fails gives a JobError in its place. `client`: a
    distributed.Client (any scheduler); None starts a LocalCluster of one single-threaded
    worker process per core for the call. `retries`: how many times a job that raised
    on its worker (not a job error: those are results) is run again.
    """
    import distributed

    jobs = list(jobs)
    results = [None] * len(jobs)
    specs = []
    for i, job in enumerate(jobs):
        try:
            if not isinstance(job, dict):
                raise TypeError(f"a job is a dict, not {type(job).__name__}")
            command, scene = job.get("command"), job.get("scene")
            if command not in _ARGUMENTS:
                raise ValueError(f"\"command\" must be \"measure\" or \"optimize\", not {command!r}")
            if not isinstance(scene, (str, os.PathLike)):
                raise ValueError("\"scene\" must be a scene file's path")
            kwargs = {k: v for k, v in job.items() if k not in ("command", "scene", "settings")}
            unknown = sorted(set(kwargs) - _ARGUMENTS[command])
            if unknown:
                raise ValueError(f"{command} takes no {', '.join(repr(k) for k in unknown)}")
            scene = os.fspath(scene)
            if not os.path.isfile(scene):
                raise FileNotFoundError(f"{scene}: cannot open the file")
            files, own, kwargs = _bundle(scene, kwargs)
            specs.append((i, {"command": command, "scene": scene, "scene_abs": os.path.abspath(scene),
                              "settings": job.get("settings"), "kwargs": kwargs, "out": kwargs.get("out"), "files": own},
                          files))
        except Exception as e:  # noqa: BLE001: a job that cannot start is its result
            results[i] = JobError(i, str(job.get("scene")) if isinstance(job, dict) else "?",
                                  str(job.get("command")) if isinstance(job, dict) else "?", type(e).__name__, str(e))

    def run(c):
        # One bundle per distinct set of files (the jobs of one scene share it), sent once.
        bundles = {}
        futures = []
        for i, spec, files in specs:
            digest = hashlib.sha1()
            for path in sorted(files):
                digest.update(path.encode() + b"\0" + hashlib.sha1(files[path]).digest())
            key = digest.hexdigest()
            if key not in bundles:
                bundles[key] = c.submit(_files, files, pure=False, key=f"luxplan-files-{key}-{os.urandom(4).hex()}")
            futures.append((i, spec, c.submit(_run_job, spec, bundles[key], pure=False, retries=retries,
                                              key=f"luxplan-{i}-{os.urandom(4).hex()}")))
        for i, spec, future in futures:
            try:
                outcome = future.result()
            except Exception as e:  # noqa: BLE001: a worker lost too often (KilledWorker), or a raise
                results[i] = JobError(i, spec["scene"], spec["command"], type(e).__name__, str(e))
                continue
            if outcome[0] == "ok":
                _, result, written = outcome
                if spec["out"] is not None:
                    for rel, data in written.items():
                        path = os.path.join(os.fspath(spec["out"]), rel)
                        os.makedirs(os.path.dirname(path), exist_ok=True)
                        tmp = path + ".tmp"
                        with open(tmp, "wb") as f:
                            f.write(data)
                        os.replace(tmp, path)
                results[i] = result
            else:
                _, kind, message, diagnostics = outcome
                results[i] = JobError(i, spec["scene"], spec["command"], kind, message, diagnostics)

    if client is not None:
        run(client)
    elif specs:
        with distributed.LocalCluster(n_workers=os.cpu_count() or 1, threads_per_worker=1, processes=True,
                                      dashboard_address=":0") as cluster, distributed.Client(cluster) as own:
            run(own)
    return results
