#!/usr/bin/env python3
"""Validates SARIF files against the published SARIF 2.1.0 JSON schema (vendored
beside this script, see README.md) plus the extra rules GitHub code scanning
applies, after checking that deliberately broken SARIF is rejected. With
--json-schema SCHEMA, validates shaderport JSON output against SCHEMA (draft-07)
instead. Uses Debian's python3-jsonschema; reads nothing from the network.

Usage: validate.py [--json-schema SCHEMA] FILE...
"""

import copy
import json
import re
import sys
from pathlib import Path

import jsonschema

SARIF_SCHEMA = Path(__file__).resolve().parent / "sarif-2.1.0-rtm.5.json"

# RFC 3986 characters; python3-jsonschema checks "uri" only with optional
# packages, so the formats the schemas use are checked here.
_URI_CHARS = re.compile(r"^(?:[A-Za-z0-9\-._~!$&'()*+,;=:@/?#\[\]]|%[0-9A-Fa-f]{2})*$")
_SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.\-]*:")


def _format_checker():
    checker = jsonschema.FormatChecker()

    @checker.checks("uri-reference")
    def is_uri_reference(value):
        return not isinstance(value, str) or bool(_URI_CHARS.match(value))

    @checker.checks("uri")
    def is_uri(value):
        return not isinstance(value, str) or (
            bool(_URI_CHARS.match(value)) and bool(_SCHEME.match(value)))

    return checker


def _schema_problems(validator, document):
    problems = []
    for error in sorted(validator.iter_errors(document), key=lambda e: list(map(str, e.path))):
        where = "/" + "/".join(str(part) for part in error.absolute_path)
        problems.append(f"{where} {error.message}")
    return problems


def compile_sarif():
    schema = json.loads(SARIF_SCHEMA.read_text(encoding="utf-8"))
    jsonschema.Draft4Validator.check_schema(schema)
    return jsonschema.Draft4Validator(schema, format_checker=_format_checker())


def compile_json_schema(path):
    schema = json.loads(Path(path).read_text(encoding="utf-8"))
    jsonschema.Draft7Validator.check_schema(schema)  # the schema itself must be valid
    return jsonschema.Draft7Validator(schema, format_checker=_format_checker())


def github_problems(log):
    """What GitHub code scanning requires beyond the schema."""
    problems = []
    if not isinstance(log, dict):
        return ["not a JSON object"]
    if log.get("version") != "2.1.0":
        problems.append("version must be 2.1.0")
    for r, run in enumerate(log.get("runs") or []):
        if not isinstance(run, dict):
            continue
        rules = (((run.get("tool") or {}).get("driver") or {}).get("rules")) or []
        ids = [rule.get("id") for rule in rules if isinstance(rule, dict)]
        if len(set(ids)) != len(ids):
            problems.append(f"run {r}: duplicate rule ids")
        for i, result in enumerate(run.get("results") or []):
            where = f"run {r} result {i}"
            if not isinstance(result, dict):
                continue
            if not result.get("ruleId"):
                problems.append(f"{where}: no ruleId")
            index = result.get("ruleIndex")
            if index is not None and (not isinstance(index, int) or index < 0 or
                                      index >= len(ids) or ids[index] != result.get("ruleId")):
                problems.append(f"{where}: ruleIndex {index} is not {result.get('ruleId')}")
            message = result.get("message")
            if not isinstance(message, dict) or not isinstance(message.get("text"), str):
                problems.append(f"{where}: no message.text")
            locations = result.get("locations") or []
            if not locations:
                problems.append(f"{where}: no location")
            for location in locations:
                physical = location.get("physicalLocation") if isinstance(location, dict) else None
                artifact = physical.get("artifactLocation") if isinstance(physical, dict) else None
                if not isinstance(artifact, dict) or not artifact.get("uri"):
                    problems.append(
                        f"{where}: a location without physicalLocation.artifactLocation.uri")
    return problems


def check_sarif(validator, log):
    return _schema_problems(validator, log) + github_problems(log)


def self_test(validator):
    """The validator must reject known-bad input before its "valid" means anything."""
    good = {
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [{
            "tool": {"driver": {"name": "t", "informationUri": "https://example.invalid/t",
                                "rules": [{"id": "a/b"}]}},
            "results": [{
                "ruleId": "a/b", "ruleIndex": 0, "level": "error", "message": {"text": "m"},
                "locations": [{"physicalLocation": {
                    "artifactLocation": {"uri": "a.frag"},
                    "region": {"startLine": 1, "startColumn": 1}}}],
            }],
        }],
    }
    problems = check_sarif(validator, good)
    if problems:
        raise RuntimeError(f"self-test: a valid SARIF log was rejected: {problems}")

    def result(log):
        return log["runs"][0]["results"][0]

    def set_key(get, key, value):
        return lambda log: get(log).__setitem__(key, value)

    breakers = {
        "wrong version": set_key(lambda log: log, "version", "2.2.0"),
        "unknown level": set_key(result, "level", "fatal"),
        "line 0": set_key(lambda log: result(log)["locations"][0]["physicalLocation"]["region"],
                          "startLine", 0),
        "unknown property": set_key(result, "severity", "error"),
        "no tool": lambda log: log["runs"][0].pop("tool"),
        "bad ruleIndex": set_key(result, "ruleIndex", 3),
        "space in a URI": set_key(lambda log: log["runs"][0]["tool"]["driver"],
                                  "informationUri", "https://example.invalid/a b"),
    }
    for name, break_it in breakers.items():
        broken = copy.deepcopy(good)
        break_it(broken)
        problems = check_sarif(validator, broken)
        if not problems:
            raise RuntimeError(f"self-test: a broken log ({name}) was accepted")
        print(f"self-test: broken SARIF ({name}) rejected: {problems[0]}")


def main(argv):
    json_schema = None
    files = []
    arguments = iter(argv)
    for argument in arguments:
        if argument == "--json-schema":
            json_schema = next(arguments, None)
        else:
            files.append(argument)
    if not files or (json_schema is None and "--json-schema" in argv):
        print("usage: validate.py [--json-schema SCHEMA] FILE...", file=sys.stderr)
        return 2
    if json_schema:
        validator = compile_json_schema(json_schema)
        for name, broken in {"an empty object": {}, "an array": []}.items():
            if not _schema_problems(validator, broken):
                raise RuntimeError(f"self-test: {name} was accepted by {json_schema}")
            print(f"self-test: {name} rejected")
    else:
        validator = compile_sarif()
        self_test(validator)
    failed = 0
    for file in files:
        document = json.loads(Path(file).read_text(encoding="utf-8"))
        problems = (_schema_problems(validator, document) if json_schema
                    else check_sarif(validator, document))
        if problems:
            failed += 1
            print(f"INVALID: {file}")
            for problem in problems:
                print(f"  {problem}")
        else:
            print(f"valid: {Path(file).name}")
    print(f"{len(files) - failed} passed, {failed} failed")
    return 0 if failed == 0 else 1


if __name__ == "__main__":
    try:
        sys.exit(main(sys.argv[1:]))
    except Exception as error:  # a crash must not look like "invalid input"
        print(f"validate.py: {type(error).__name__}: {error}", file=sys.stderr)
        sys.exit(2)
