#!/usr/bin/env python3
"""Validate fftess JSON reports against docs/schema (JSON Schema 2020-12).

    validate_json.py SCHEMA_DIR FILE...

Each FILE holds one report (a JSON object; a sweep report is one object even though the CLI streams it), or JSON
lines (one report per line). The schema is SCHEMA_DIR/<kind>.schema.json, picked by the report's "kind"; relative
"$ref"s resolve to the files in SCHEMA_DIR (common.schema.json). Exit status: 0 every report is valid, 1 a report is
invalid or unreadable (each error printed as FILE: JSON-POINTER: message), 2 usage (no such schema directory, no file).
Needs python3-jsonschema (Debian; 4.10 or later).
"""
import json
import os
import sys
import urllib.parse
import urllib.request

import jsonschema


def load_schemas(schema_dir):
    """All *.schema.json of schema_dir: {kind: schema}, and the store of every schema by its absolute URI."""
    base = urllib.parse.urljoin("file:", urllib.request.pathname2url(os.path.abspath(schema_dir)) + "/")
    schemas, store = {}, {}
    for name in sorted(os.listdir(schema_dir)):
        if not name.endswith(".schema.json"):
            continue
        with open(os.path.join(schema_dir, name), encoding="utf-8") as f:
            schema = json.load(f)
        jsonschema.Draft202012Validator.check_schema(schema)
        uri = urllib.parse.urljoin(base, schema.get("$id", name))
        store[uri] = schema
        store[urllib.parse.urljoin(base, name)] = schema
        schemas[name[: -len(".schema.json")]] = (uri, schema)
    return schemas, store


def reports_of(path):
    """The reports in a file: one JSON document, or JSON lines."""
    with open(path, encoding="utf-8") as f:
        text = f.read()
    try:
        return [("", json.loads(text))]
    except json.JSONDecodeError as whole:
        lines = [(n, l) for n, l in enumerate(text.splitlines(), 1) if l.strip()]
        if len(lines) < 2:
            raise whole
        return [(":%d" % n, json.loads(l)) for n, l in lines]


def pointer(path):
    return "/" + "/".join(str(p).replace("~", "~0").replace("/", "~1") for p in path)


_validators = {}


def validator_for(schemas, store, kind):
    """A Draft 2020-12 validator of the kind's schema whose relative $refs resolve to the other schema files: through
    the referencing library where jsonschema has it (4.18 and later), else through RefResolver (Debian 12's 4.10).
    One per kind and schema set."""
    key = (id(schemas), kind)
    if key not in _validators:
        _validators[key] = make_validator(schemas, store, kind)
    return _validators[key]


def make_validator(schemas, store, kind):
    uri, schema = schemas[kind]
    try:
        import referencing
        import referencing.jsonschema
    except ImportError:
        resolver = jsonschema.RefResolver(base_uri=uri, referrer=schema, store=store)
        return jsonschema.Draft202012Validator(schema, resolver=resolver)
    draft = referencing.jsonschema.DRAFT202012
    registry = referencing.Registry().with_resources(
        [(u, draft.create_resource(s)) for u, s in store.items()] +
        [(s["$id"], draft.create_resource(s)) for _, s in schemas.values() if "$id" in s])
    return jsonschema.Draft202012Validator(schema, registry=registry)


def validate(schemas, store, where, report):
    """The errors of one report: [(json pointer, message)]."""
    if not isinstance(report, dict):
        return [("", "not a JSON object (a report is an object with version, kind, fftess_version)")]
    kind = report.get("kind")
    if not isinstance(kind, str) or kind not in schemas or kind == "common":
        return [("/kind", "no schema for kind %s (known: %s)" % (json.dumps(kind), ", ".join(sorted(
            k for k in schemas if k != "common"))))]
    validator = validator_for(schemas, store, kind)
    errors = sorted(validator.iter_errors(report), key=lambda e: list(map(str, e.absolute_path)))
    return [(pointer(e.absolute_path), message(e)) for e in errors]


def message(error):
    """The error's message, short; for oneOf / anyOf the closest alternative's error too."""
    text = error.message if len(error.message) <= 200 else error.message[:200] + "..."
    if error.context:
        best = jsonschema.exceptions.best_match(error.context)
        text = "matches no alternative of %s; the closest: %s: %s" % (
            error.validator, pointer(best.absolute_path), message(best))
    return text


def main(argv):
    if len(argv) < 3 or argv[1] in ("-h", "--help"):
        print(__doc__.strip(), file=sys.stderr)
        return 2
    schema_dir, files = argv[1], argv[2:]
    if not os.path.isdir(schema_dir):
        print("validate_json.py: %s: not a directory" % schema_dir, file=sys.stderr)
        return 2
    schemas, store = load_schemas(schema_dir)
    bad = 0
    for path in files:
        try:
            reports = reports_of(path)
        except (OSError, ValueError) as e:
            print("%s: %s" % (path, e))
            bad += 1
            continue
        for where, report in reports:
            errors = validate(schemas, store, where, report)
            for ptr, message in errors[:20]:
                print("%s%s: %s: %s" % (path, where, ptr or "/", message))
            if len(errors) > 20:
                print("%s%s: ... %d more errors" % (path, where, len(errors) - 20))
            bad += bool(errors)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
