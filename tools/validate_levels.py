#!/usr/bin/env python3
"""Validates levels against levels/schema/level.schema.json with an independent JSON Schema validator
(python3-jsonschema, draft 2020-12).

  * every bundled level (levels/*.json except the manifest, levels/structures/*.json, levels/parts/*.json,
    levels/lessons/*.json and levels/endless/*.json) must be valid;
  * the schema's material, bird and pig names must be the catalog's (assets/catalog.json);
  * every file of the malformed suite must be rejected by the schema, except those listed in
    schema-valid.txt: their errors are geometric or semantic, which no schema can express, and the
    schema must accept them (so loader and schema agree on everything a schema can say);
  * text: both schemas reject every C0/C1 control, DEL and bidirectional control (U+202A-U+202E,
    U+2066-U+2069) in any string or key, at any depth, and accept every other character, as the
    loader does (tests/level/SafeTextTest.cpp checks the loader against the same rule).

Usage: validate_levels.py SOURCE_DIR
"""
import importlib.metadata
import json
import re
import pathlib
import sys

try:
    import jsonschema
except ImportError:
    sys.exit("validate_levels.py: needs python3-jsonschema (Debian package; see tools/packages.txt)")


def strict_load(path):
    """JSON as the level loader reads it: UTF-8, no NaN/Infinity literals, no duplicate keys."""

    def no_constants(name):
        raise ValueError(f"{name} is not JSON")

    def no_duplicates(pairs):
        keys = [k for k, _ in pairs]
        if len(keys) != len(set(keys)):
            raise ValueError("duplicate key")
        return dict(pairs)

    text = path.read_bytes().decode("utf-8")
    return json.loads(text, parse_constant=no_constants, object_pairs_hook=no_duplicates)


def unsafe(code_point):
    """The rule as the issue states it, independently of the schema's pattern."""
    return (code_point <= 0x1F or 0x7F <= code_point <= 0x9F or 0x202A <= code_point <= 0x202E
            or 0x2066 <= code_point <= 0x2069)


def check_text_rule(level_validator, campaign_validator, level_schema):
    failures = []
    # The pattern itself, over every code point (surrogates cannot occur in decoded JSON text).
    pattern = re.compile(level_schema["$defs"]["text"]["not"]["pattern"])
    for code_point in range(0x110000):
        if 0xD800 <= code_point <= 0xDFFF:
            continue
        if bool(pattern.search("a" + chr(code_point) + "b")) != unsafe(code_point):
            failures.append(f"schema text pattern disagrees with the rule at U+{code_point:04X}")
    # Whole documents: every unsafe character, and a sample of safe ones, in each kind of place.
    level = {"format": 1, "id": "t", "title": "T", "slingshot": {"x": 0, "y": 1.5}, "birds": ["red"],
             "pigs": [{"type": "small", "x": 10, "y": 0.25}]}
    campaign = {"format": 1, "episodes": [{"id": "1", "title": "E", "levels": ["a.json"]}]}
    safe_sample = [0x20, 0x7E, 0xA0, 0xB5, 0xE9, 0x200E, 0x200F, 0x2028, 0x2065, 0x206A, 0xFEFF, 0x1F426]
    for code_point in [c for c in range(0x206A) if unsafe(c)] + safe_sample:
        text = "x" + chr(code_point) + "y"
        documents = [
            (level_validator, {**level, "title": text}),
            (level_validator, {**level, "hints": [text]}),
            (level_validator, {**level, "slingshot": {"x": 0, "y": 1.5, text: 1}}),
            (level_validator, {**level, "pigs": [{"type": text, "x": 10, "y": 0.25}]}),
            (campaign_validator, {**campaign, "episodes": [{"id": "1", "title": text, "levels": ["a.json"]}]}),
            (campaign_validator, {**campaign, "episodes": [{"id": "1", "levels": [text]}]}),
        ]
        for index, (validator, document) in enumerate(documents):
            errors = list(validator.iter_errors(document))
            text_errors = [e for e in errors if "should not be valid" in e.message]
            if unsafe(code_point) and not text_errors:
                failures.append(f"text rule: U+{code_point:04X} accepted in document {index}")
            if not unsafe(code_point) and text_errors:
                failures.append(f"text rule: U+{code_point:04X} rejected in document {index}")
    return failures


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".")
    schema = json.loads((root / "levels/schema/level.schema.json").read_text())
    jsonschema.Draft202012Validator.check_schema(schema)
    validator = jsonschema.Draft202012Validator(schema)
    failures = []

    campaign_schema = json.loads((root / "levels/schema/campaign.schema.json").read_text())
    jsonschema.Draft202012Validator.check_schema(campaign_schema)
    for error in jsonschema.Draft202012Validator(campaign_schema).iter_errors(
            strict_load(root / "levels/campaign.json")):
        failures.append(f"levels/campaign.json: {error.json_path}: {error.message}")

    levels = sorted(p for p in (root / "levels").glob("*.json") if p.name != "campaign.json")
    levels += sorted((root / "levels/structures").glob("*.json"))  # the stress scenes as level files
    levels += sorted((root / "levels/parts").glob("*.json"))  # the castle parts (tools/levelgen/parts.py)
    levels += sorted((root / "levels/lessons").glob("*.json"))  # the lessons of the title menu
    levels += sorted((root / "levels/endless").glob("*.json"))  # the endless mode's shipped first levels
    for path in levels:
        for error in validator.iter_errors(strict_load(path)):
            failures.append(f"{path.relative_to(root)}: {error.json_path}: {error.message}")

    catalog = json.loads((root / "assets/catalog.json").read_text())
    item_props = schema["properties"]
    enums = {
        "materials": item_props["blocks"]["items"]["properties"]["material"]["enum"],
        "birds": item_props["birds"]["items"]["enum"],
        "pigs": item_props["pigs"]["items"]["properties"]["type"]["enum"],
    }
    # A level's own bird is "custom" in its birds list; its material overrides are keyed by material name.
    extra = {"birds": ["custom"]}
    enums["material overrides"] = list(item_props["materials"]["properties"])
    for table, names in enums.items():
        source = "materials" if table == "material overrides" else table
        expected = [entry["name"] for entry in catalog[source]] + extra.get(table, [])
        if sorted(names) != sorted(expected):
            failures.append(f"schema {table} {names} differ from assets/catalog.json {expected}")

    # One launch-speed cap: the schema's largest reference-shot speed is the catalog's.
    cap = catalog["slingshot"]["max_launch_speed_mps"]
    schema_cap = item_props["reference_shot"]["prefixItems"][1]["maximum"]
    if schema_cap != cap:
        failures.append(f"schema reference_shot speed maximum {schema_cap} differs from the catalog's "
                        f"slingshot.max_launch_speed_mps {cap}")

    malformed = root / "tests/level/malformed"
    semantic = set()
    listing = malformed / "schema-valid.txt"
    if listing.exists():
        for line in listing.read_text().splitlines():
            line = line.split("#", 1)[0].strip()
            if line:
                semantic.add(line)
    checked = 0
    for path in sorted(malformed.glob("*.json")):
        checked += 1
        try:
            document = strict_load(path)
        except (UnicodeDecodeError, ValueError):
            document = None  # not JSON at all: both reject it
        valid = document is not None and validator.is_valid(document)
        if path.stem in semantic and not valid:
            reason = "not JSON" if document is None else next(validator.iter_errors(document)).message
            failures.append(f"{path.name}: listed in schema-valid.txt but the schema rejects it ({reason})")
        elif path.stem not in semantic and valid:
            failures.append(f"{path.name}: the loader rejects it but the schema accepts it")

    failures += check_text_rule(validator, jsonschema.Draft202012Validator(campaign_schema), schema)

    for failure in failures:
        print(failure)
    print(f"{len(levels)} levels and {checked} malformed files checked against the schema "
          f"(jsonschema {importlib.metadata.version('jsonschema')}): {len(failures)} problem(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
