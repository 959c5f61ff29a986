#!/usr/bin/env python3
"""Validates levels against levels/schema/level.schema.json with an independent JSON Schema validator
(python3-jsonschema, draft 2020-12).

  * every bundled level (levels/*.json except the manifest) must be valid;
  * the schema's material, bird and pig names must be the catalog's (assets/catalog.json);
  * every file of the malformed suite must be rejected by the schema, except those listed in
    schema-valid.txt: their errors are geometric or semantic, which no schema can express, and the
    schema must accept them (so loader and schema agree on everything a schema can say).

Usage: validate_levels.py SOURCE_DIR
"""
import importlib.metadata
import json
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

    for failure in failures:
        print(failure)
    print(f"{len(levels)} levels and {checked} malformed files checked against the schema "
          f"(jsonschema {importlib.metadata.version('jsonschema')}): {len(failures)} problem(s)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
