#!/usr/bin/env python3
"""Writes the regression inputs that are too large to commit, into OUT_DIR/<target>/, beside the committed ones in
fuzz/regressions/. Each is a crash class found before the fuzzers existed: nesting deep enough to exhaust the stack
of a recursive reader.
Usage: make_regressions.py OUT_DIR
"""
import pathlib
import sys

DEPTH = 50_000


def nested_arrays(depth):
    return "[" * depth + "]" * depth


def nested_objects(depth):
    return '{"a":' * depth + "{}" + "}" * depth


def main():
    out = pathlib.Path(sys.argv[1])
    scenes = out / "scene_json_fuzzer"
    models = out / "gltf_fuzzer"
    for folder in (scenes, models):
        folder.mkdir(parents=True, exist_ok=True)
    (scenes / "deep-arrays.json").write_text(nested_arrays(DEPTH))
    (scenes / "deep-objects.json").write_text(nested_objects(DEPTH))
    (scenes / "deep-camera.json").write_text('{"camera": %s}' % nested_arrays(DEPTH))
    asset = '"asset": {"version": "2.0"}'
    (models / "deep-extras-arrays.gltf").write_text('{%s, "extras": %s}' % (asset, nested_arrays(DEPTH)))
    (models / "deep-extras-objects.gltf").write_text('{%s, "extras": %s}' % (asset, nested_objects(DEPTH)))


if __name__ == "__main__":
    main()
