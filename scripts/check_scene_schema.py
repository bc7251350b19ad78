#!/usr/bin/env python3
"""Validates every scenes/*.json against docs/tracer/scene.schema.json (python3-jsonschema), and checks
that a few broken scenes are refused. Usage: scripts/check_scene_schema.py"""
import copy, json, pathlib, sys
import jsonschema

ROOT = pathlib.Path(__file__).resolve().parent.parent
schema = json.loads((ROOT / "docs" / "tracer" / "scene.schema.json").read_text())
jsonschema.Draft202012Validator.check_schema(schema)
v = jsonschema.Draft202012Validator(schema)
bad = 0
scenes = sorted((ROOT / "scenes").glob("*.json"))
for f in scenes:
    errors = list(v.iter_errors(json.loads(f.read_text())))
    for e in errors:
        print(f"{f.name}: {'/'.join(map(str, e.absolute_path))}: {e.message}")
    bad += bool(errors)
base = json.loads((ROOT / "scenes" / "diffuse-convex.json").read_text())
for patch in ({"max_depth": 17}, {"camera": {**base["camera"], "window": [0, 1, 0, 1]}}, {"sampling": {"type": "regular"}},
              {"objects": [{"type": "torus", "material": "matte"}]}, {"colour": 1}):
    s = copy.deepcopy(base)
    s.update(patch)
    if v.is_valid(s):
        print(f"schema accepts a broken scene: {patch}")
        bad += 1
print(f"{len(scenes)} scenes checked, {bad} problems")
sys.exit(1 if bad else 0)
