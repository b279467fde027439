#!/usr/bin/env python3
"""Validates SARIF files against the published SARIF 2.1.0 JSON schema (vendored
beside this script, see README.md), the extra rules GitHub code scanning applies
and the error- and warning-level rules of Microsoft's SARIF validator
(`Sarif.Multitool validate`, reimplemented below), after checking that
deliberately broken SARIF is rejected, each Multitool rule by its own broken log.
With --json-schema SCHEMA, validates shaderport JSON output against SCHEMA
(draft-07) instead. Uses Debian's python3-jsonschema; reads nothing from the network.

Usage: validate.py [--json-schema SCHEMA] FILE...
"""

import datetime
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


# --- Sarif.Multitool `validate` rules -------------------------------------------------
# Our own reading of the rules of Microsoft's SARIF validator (sarif-sdk,
# src/Sarif.Multitool.Library/Rules) that run by default (rule kind "Sarif") at level
# error or warning: `Sarif.Multitool validate` reports those two levels by default.
# The note-level rules (SARIF2002, 2003, 2006, 2009-2016) are advice and not checked.
# Every rule is a function named after the rule that yields "SARIFnnnn: <path>: what".

# What a SARIF object's property holds: (parent kind, property) -> child kind. Arrays
# hold that kind; "map:" marks an object whose values are of that kind.
_CHILD_KINDS = {
    ("log", "runs"): "run",
    ("run", "tool"): "tool",
    ("run", "results"): "result",
    ("run", "invocations"): "invocation",
    ("run", "artifacts"): "artifact",
    ("run", "originalUriBaseIds"): "map:artifactLocation",
    ("run", "versionControlProvenance"): "versionControlDetails",
    ("run", "logicalLocations"): "logicalLocation",
    ("run", "addresses"): "address",
    ("run", "threadFlowLocations"): "threadFlowLocation",
    ("run", "webRequests"): "webRequest",
    ("run", "webResponses"): "webResponse",
    ("run", "graphs"): "graph",
    ("run", "conversion"): "conversion",
    ("conversion", "analysisToolLogFiles"): "artifactLocation",
    ("tool", "driver"): "toolComponent",
    ("tool", "extensions"): "toolComponent",
    ("toolComponent", "rules"): "reportingDescriptor",
    ("toolComponent", "notifications"): "reportingDescriptor",
    ("result", "analysisTarget"): "artifactLocation",
    ("result", "locations"): "location",
    ("result", "relatedLocations"): "location",
    ("result", "rule"): "reportingDescriptorReference",
    ("result", "codeFlows"): "codeFlow",
    ("result", "stacks"): "stack",
    ("result", "fixes"): "fix",
    ("result", "attachments"): "attachment",
    ("result", "provenance"): "resultProvenance",
    ("result", "graphs"): "graph",
    ("result", "graphTraversals"): "graphTraversal",
    ("result", "webRequest"): "webRequest",
    ("result", "webResponse"): "webResponse",
    ("resultProvenance", "conversionSources"): "physicalLocation",
    ("location", "physicalLocation"): "physicalLocation",
    ("location", "logicalLocations"): "logicalLocation",
    ("physicalLocation", "artifactLocation"): "artifactLocation",
    ("physicalLocation", "region"): "region",
    ("physicalLocation", "contextRegion"): "region",
    ("physicalLocation", "address"): "address",
    ("artifact", "location"): "artifactLocation",
    ("fix", "artifactChanges"): "artifactChange",
    ("artifactChange", "artifactLocation"): "artifactLocation",
    ("artifactChange", "replacements"): "replacement",
    ("replacement", "deletedRegion"): "region",  # the Multitool does not look here; we do
    ("attachment", "artifactLocation"): "artifactLocation",
    ("attachment", "regions"): "region",
    ("codeFlow", "threadFlows"): "threadFlow",
    ("threadFlow", "locations"): "threadFlowLocation",
    ("threadFlowLocation", "location"): "location",
    ("stack", "frames"): "stackFrame",
    ("stackFrame", "location"): "location",
    ("graph", "nodes"): "node",
    ("node", "location"): "location",
    ("node", "children"): "node",
    ("invocation", "executableLocation"): "artifactLocation",
    ("invocation", "responseFiles"): "artifactLocation",
    ("invocation", "stdin"): "artifactLocation",
    ("invocation", "stdout"): "artifactLocation",
    ("invocation", "stderr"): "artifactLocation",
    ("invocation", "stdoutStderr"): "artifactLocation",
    ("invocation", "toolExecutionNotifications"): "notification",
    ("invocation", "toolConfigurationNotifications"): "notification",
    ("notification", "locations"): "location",
    ("versionControlDetails", "mappedTo"): "artifactLocation",
}


class _Node:
    """A SARIF object found in a log: its kind, its path and the run/result it is in."""

    def __init__(self, kind, path, value, run, result):
        self.kind, self.path, self.value, self.run, self.result = kind, path, value, run, result

    @property
    def where(self):
        return _where(self.path)


def _where(path):
    """A path as the Multitool prints it: runs[0].results[2].locations[0]."""
    text = ""
    for token in path:
        if isinstance(token, int):
            text += f"[{token}]"
        elif re.match(r"^[$_A-Za-z][$_A-Za-z0-9]*$", token):
            text += ("." if text else "") + token
        else:
            text += f"['{token}']"
    return text or "(the log)"


def _sarif_objects(log):
    """Every SARIF object of the log that a rule may look at, parents first."""
    nodes = []

    def visit(kind, path, value, run, result):
        if not isinstance(value, dict):
            return
        run = value if kind == "run" else run
        result = value if kind == "result" else result
        nodes.append(_Node(kind, path, value, run, result))
        for key, child in value.items():
            child_kind = _CHILD_KINDS.get((kind, key))
            if child_kind is None:
                continue
            if child_kind.startswith("map:"):
                if isinstance(child, dict):
                    for name, entry in child.items():
                        visit(child_kind[4:], path + (key, name), entry, run, result)
            elif isinstance(child, list):
                for i, entry in enumerate(child):
                    visit(child_kind, path + (key, i), entry, run, result)
            else:
                visit(child_kind, path + (key,), child, run, result)

    visit("log", (), log, None, None)
    return nodes


def _of_kind(nodes, kind):
    return [node for node in nodes if node.kind == kind]


def _dict(value):
    return value if isinstance(value, dict) else {}


def _list(value):
    return value if isinstance(value, list) else []


def _index(value):
    """An index-valued property; -1 (SARIF's "absent") when it is absent or not an integer."""
    return value if isinstance(value, int) and not isinstance(value, bool) else -1


def _driver(run):
    return _dict(_dict(_dict(run).get("tool")).get("driver"))


# RFC 3986: the parts of a URI reference (appendix B) and what each part may hold.
_URI_PARTS = re.compile(r"^(?:([^:/?#]+):)?(?://([^/?#]*))?([^?#]*)(?:\?([^#]*))?(?:#(.*))?$")
_SCHEME_SYNTAX = re.compile(r"^[A-Za-z][A-Za-z0-9+.\-]*$")
_PCHAR = r"[A-Za-z0-9\-._~!$&'()*+,;=:@]|%[0-9A-Fa-f]{2}"
_AUTHORITY_SYNTAX = re.compile(rf"^(?:{_PCHAR}|[\[\]])*$")
_PATH_SYNTAX = re.compile(rf"^(?:{_PCHAR}|/)*$")
_QUERY_SYNTAX = re.compile(rf"^(?:{_PCHAR}|[/?])*$")


def _uri_parts(uri):
    """(scheme, authority, path, query, fragment) of a valid URI reference, else None."""
    if not isinstance(uri, str):
        return None
    parts = _URI_PARTS.match(uri)
    if parts is None:
        return None
    scheme, authority, path, query, fragment = parts.groups()
    if scheme is not None and not _SCHEME_SYNTAX.match(scheme):
        return None
    if authority is not None and not _AUTHORITY_SYNTAX.match(authority):
        return None
    if not _PATH_SYNTAX.match(path):
        return None
    if any(part is not None and not _QUERY_SYNTAX.match(part) for part in (query, fragment)):
        return None
    return scheme, authority, path, query, fragment


def _is_absolute_uri(uri):
    parts = _uri_parts(uri)
    return parts is not None and parts[0] is not None


# The URI-valued properties SARIF1002 and SARIF1005 look at: (kind, property, is an array).
_CHECKED_URIS = [
    ("log", "$schema", False),
    ("result", "workItemUris", True),
    ("reportingDescriptor", "helpUri", False),
    ("toolComponent", "downloadUri", False),
    ("versionControlDetails", "repositoryUri", False),
]


def _checked_uris(nodes):
    """(path, uri) of every URI-valued property SARIF1002/SARIF1005 check but artifact URIs."""
    for kind, key, is_array in _CHECKED_URIS:
        for node in _of_kind(nodes, kind):
            value = node.value.get(key)
            if is_array:
                for i, uri in enumerate(_list(value)):
                    yield node.path + (key, i), uri
            elif value is not None:
                yield node.path + (key,), value


MULTITOOL_RULES = []


def multitool_rule(level):
    def register(function):
        MULTITOOL_RULES.append((function.__name__.split("_")[0], level, function))
        return function
    return register


@multitool_rule("error")
def SARIF1002_UrisMustBeValid(log, nodes):
    uris = list(_checked_uris(nodes))
    for node in _of_kind(nodes, "artifactLocation"):
        if "uri" in node.value:
            uris.append((node.path + ("uri",), node.value["uri"]))
    for path, uri in uris:
        if not isinstance(uri, str):
            continue
        parts = _uri_parts(uri)
        if parts is None:
            yield f"SARIF1002: {_where(path)}: '{uri}' is not a valid URI reference (RFC 3986)"
        elif parts[0] is not None and parts[0].lower() == "file" and ".." in uri.split("/"):
            yield f"SARIF1002: {_where(path)}: the file URI '{uri}' has a '..' segment"


@multitool_rule("error")
def SARIF1004_ExpressUriBaseIdsCorrectly(log, nodes):
    for node in _of_kind(nodes, "artifactLocation"):
        uri = node.value.get("uri")
        if not isinstance(uri, str):
            continue
        if "uriBaseId" in node.value and _is_absolute_uri(uri):
            yield (f"SARIF1004: {node.where}: has uriBaseId '{node.value['uriBaseId']}' but its "
                   f"uri '{uri}' is absolute")
        if not _is_absolute_uri(uri) and uri.startswith("/"):
            yield (f"SARIF1004: {_where(node.path + ('uri',))}: the relative reference '{uri}' "
                   "begins with a slash")
    for run in _of_kind(nodes, "run"):
        for name, base in _dict(run.value.get("originalUriBaseIds")).items():
            uri = _dict(base).get("uri")
            if _uri_parts(uri) is None:
                continue  # SARIF1002's business
            where = _where(run.path + ("originalUriBaseIds", name))
            if "uriBaseId" not in base and not _is_absolute_uri(uri):
                yield f"SARIF1004: {where}: top-level base '{uri}' is not an absolute URI"
            if not uri.endswith("/"):
                yield f"SARIF1004: {where}: '{uri}' does not end with a slash"
            if ".." in uri.split("/"):
                yield f"SARIF1004: {where}: '{uri}' has a '..' segment"
            _, _, _, query, fragment = _uri_parts(uri)
            if _is_absolute_uri(uri) and (query or fragment):
                yield f"SARIF1004: {where}: '{uri}' has a query or a fragment"


@multitool_rule("error")
def SARIF1005_UriMustBeAbsolute(log, nodes):
    for path, uri in _checked_uris(nodes):
        if _uri_parts(uri) is not None and not _is_absolute_uri(uri):
            yield f"SARIF1005: {_where(path)}: '{uri}' must be an absolute URI"


def _utc(value):
    try:
        moment = datetime.datetime.fromisoformat(value.replace("Z", "+00:00"))
    except (AttributeError, ValueError):
        return None
    return moment if moment.tzinfo else moment.replace(tzinfo=datetime.timezone.utc)


@multitool_rule("error")
def SARIF1006_InvocationPropertiesMustBeConsistent(log, nodes):
    for node in _of_kind(nodes, "invocation"):
        start, end = _utc(node.value.get("startTimeUtc")), _utc(node.value.get("endTimeUtc"))
        if start and end and start > end:
            yield f"SARIF1006: {node.where}.endTimeUtc: precedes startTimeUtc"


def _region_kinds(region):
    """Which of SARIF's three region forms a region uses (SARIF 3.30)."""
    return {
        "lines": _index(region.get("startLine")) >= 1,
        "chars": _index(region.get("charOffset")) >= 0,
        "bytes": _index(region.get("byteOffset")) >= 0,
    }


@multitool_rule("error")
def SARIF1007_RegionPropertiesMustBeConsistent(log, nodes):
    for node in _of_kind(nodes, "region"):
        region = node.value
        if not any(_region_kinds(region).values()):
            yield f"SARIF1007: {node.where}: has none of startLine, charOffset, byteOffset"
        start_line = max(_index(region.get("startLine")), 0)
        if "endLine" in region and _index(region["endLine"]) < start_line:
            yield f"SARIF1007: {node.where}.endLine: {region['endLine']} is before startLine"
        one_line = "endLine" not in region or region["endLine"] == region.get("startLine")
        start_column = max(_index(region.get("startColumn")), 0)
        if one_line and "endColumn" in region and _index(region["endColumn"]) < start_column:
            yield (f"SARIF1007: {node.where}.endColumn: {region['endColumn']} is before "
                   f"startColumn {start_column} on the same line")


def _with_defaults(region):
    """A region's properties with SARIF's defaults filled in (as the Multitool compares)."""
    full = {key: _index(region.get(key)) for key in
            ("startLine", "startColumn", "endLine", "endColumn", "charOffset", "charLength",
             "byteOffset", "byteLength")}
    if full["startLine"] >= 1:
        full["endLine"] = full["endLine"] if full["endLine"] > 0 else full["startLine"]
        full["startColumn"] = full["startColumn"] if full["startColumn"] > 0 else 1
        full["endColumn"] = full["endColumn"] if full["endColumn"] > 0 else sys.maxsize
    full["charLength"] = max(full["charLength"], 0)
    full["byteLength"] = max(full["byteLength"], 0)
    return full


def _is_proper_superset(outer, inner):
    kinds_outer, kinds_inner = _region_kinds(outer), _region_kinds(inner)
    o, i = _with_defaults(outer), _with_defaults(inner)
    if kinds_outer["lines"] and kinds_inner["lines"]:
        same = all(o[k] == i[k] for k in ("startLine", "startColumn", "endLine", "endColumn"))
        if (o["startLine"] > i["startLine"] or o["endLine"] < i["endLine"] or same or
                (o["startLine"] == i["startLine"] and o["startColumn"] > i["startColumn"]) or
                (o["endLine"] == i["endLine"] and o["endColumn"] < i["endColumn"])):
            return False
    for offset, length in (("charOffset", "charLength"), ("byteOffset", "byteLength")):
        form = "chars" if offset == "charOffset" else "bytes"
        if kinds_outer[form] and kinds_inner[form]:
            if (o[offset] > i[offset] or o[offset] + o[length] < i[offset] + i[length] or
                    (o[offset] == i[offset] and o[length] <= i[length])):
                return False
    return True


@multitool_rule("error")
def SARIF1008_PhysicalLocationPropertiesMustBeConsistent(log, nodes):
    for node in _of_kind(nodes, "physicalLocation"):
        context, region = node.value.get("contextRegion"), node.value.get("region")
        if not isinstance(context, dict):
            continue
        if not isinstance(region, dict):
            yield f"SARIF1008: {node.where}: has a contextRegion but no region"
        elif not _is_proper_superset(context, region):
            yield f"SARIF1008: {node.where}: contextRegion is not a proper superset of region"


# Index-valued properties and the run array each points into: kind -> [(property, array)].
_INDEXED_ARRAYS = {
    "address": [("index", "addresses"), ("parentIndex", "addresses")],
    "artifact": [("parentIndex", "artifacts")],
    "artifactLocation": [("index", "artifacts")],
    "logicalLocation": [("index", "logicalLocations"), ("parentIndex", "logicalLocations")],
    "result": [("ruleIndex", "tool.driver.rules")],
    "resultProvenance": [("invocationIndex", "invocations")],
    "threadFlowLocation": [("index", "threadFlowLocations")],
    "webRequest": [("index", "webRequests")],
    "webResponse": [("index", "webResponses")],
    "graphTraversal": [("runGraphIndex", "graphs"), ("resultGraphIndex", "result:graphs")],
}


@multitool_rule("error")
def SARIF1009_IndexPropertiesMustBeConsistentWithArrays(log, nodes):
    for node in nodes:
        for key, array_path in _INDEXED_ARRAYS.get(node.kind, []):
            index = _index(node.value.get(key))
            if index == -1:
                continue
            in_result = array_path.startswith("result:")
            array = node.result if in_result else node.run
            for part in array_path[len("result:") if in_result else 0:].split("."):
                array = _dict(array).get(part)
            name = (f"the result's {array_path[len('result:'):]}" if in_result
                    else f"runs[{node.path[1]}].{array_path}")
            if not isinstance(array, list):
                yield f"SARIF1009: {node.where}.{key}: is {index} but {name} is absent"
            elif index >= len(array):
                yield (f"SARIF1009: {node.where}.{key}: is {index} but {name} has "
                       f"{len(array)} elements")


@multitool_rule("error")
def SARIF1010_RuleIdMustBeConsistent(log, nodes):
    for node in _of_kind(nodes, "result"):
        rule_id = node.value.get("ruleId")
        reference_id = _dict(node.value.get("rule")).get("id")
        if rule_id is None and reference_id is None:
            yield f"SARIF1010: {node.where}: has neither ruleId nor rule.id"
        elif rule_id is not None and reference_id is not None and rule_id != reference_id:
            yield f"SARIF1010: {node.where}: ruleId '{rule_id}' is not rule.id '{reference_id}'"


@multitool_rule("error")
def SARIF1011_ReferenceFinalSchema(log, nodes):
    schema = _dict(log).get("$schema")
    if isinstance(schema, str) and not schema.endswith(("2.1.0", "2.1.0.json")):
        yield f"SARIF1011: $schema: '{schema}' is not the final SARIF 2.1.0 schema"


def _rule_of(result, run):
    """The driver rule a result refers to (by ruleIndex, then by id), or None."""
    rules = _list(_driver(run).get("rules"))
    index = _index(result.get("ruleIndex"))
    if index == -1:
        index = _index(_dict(result.get("rule")).get("index"))
    if index != -1:
        return _dict(rules[index]) if index < len(rules) else None
    rule_id = result.get("ruleId", _dict(result.get("rule")).get("id"))
    return next((rule for rule in rules if _dict(rule).get("id") == rule_id), None)


@multitool_rule("error")
def SARIF1012_MessageArgumentsMustBeConsistentWithRule(log, nodes):
    for node in _of_kind(nodes, "result"):
        message = _dict(node.value.get("message"))
        message_id = message.get("id")
        if not message_id:
            continue
        strings = _dict(_dict(_rule_of(node.value, node.run)).get("messageStrings"))
        if message_id not in strings:
            yield f"SARIF1012: {node.where}: its rule has no message string '{message_id}'"
            continue
        text = _dict(strings[message_id]).get("text") or ""
        needed = max((int(n) + 1 for n in re.findall(r"\{(\d+)\}", text)), default=0)
        given = len(_list(message.get("arguments")))
        if needed > given:
            yield (f"SARIF1012: {node.where}: message '{message_id}' needs {needed} "
                   f"arguments, has {given}")


def _resolve_json_pointer(document, pointer):
    if pointer == "":
        return True
    if not pointer.startswith("/"):
        return False
    for token in pointer[1:].split("/"):
        token = token.replace("~1", "/").replace("~0", "~")
        if isinstance(document, dict) and token in document:
            document = document[token]
        elif isinstance(document, list) and token.isdigit() and int(token) < len(document):
            document = document[int(token)]
        else:
            return False
    return True


@multitool_rule("error")
def SARIF1013_SarifReferencesMustResolve(log, nodes):
    for node in _of_kind(nodes, "artifactLocation"):
        uri = node.value.get("uri")
        if isinstance(uri, str) and uri.startswith("sarif:"):
            if not _resolve_json_pointer(log, uri[len("sarif:"):]):
                yield f"SARIF1013: {node.where}: '{uri}' does not resolve within the log"


@multitool_rule("warning")
def SARIF1001_RuleIdentifiersMustBeValid(log, nodes):
    for node in _of_kind(nodes, "reportingDescriptor"):
        rule_id, name = node.value.get("id"), node.value.get("name")
        if isinstance(rule_id, str) and isinstance(name, str) and rule_id.lower() == name.lower():
            yield f"SARIF1001: {node.where}: name '{name}' is the same as id '{rule_id}'"


@multitool_rule("warning")
def SARIF2001_TerminateMessagesWithPeriod(log, nodes):
    for run in _of_kind(nodes, "run"):
        for r, rule in enumerate(_list(_driver(run.value).get("rules"))):
            for key, string in _dict(_dict(rule).get("messageStrings")).items():
                text = _dict(string).get("text")
                if isinstance(text, str) and text and not text.endswith("."):
                    where = _where(run.path + ("tool", "driver", "rules", r, "messageStrings",
                                               key, "text"))
                    yield f"SARIF2001: {where}: does not end with a period"


@multitool_rule("warning")
def SARIF2004_OptimizeFileSize(log, nodes):
    for node in nodes:  # sentinel indexes: -1 means "absent", so leave the property out
        for key in {"artifactLocation": ["index"], "reportingDescriptorReference": ["index"],
                    "threadFlowLocation": ["index"], "logicalLocation": ["index", "parentIndex"],
                    "address": ["index", "parentIndex"], "artifact": ["parentIndex"],
                    "result": ["ruleIndex"]}.get(node.kind, []):
            if node.value.get(key) == -1:
                yield f"SARIF2004: {node.where}.{key}: is -1, which means absent: leave it out"
    for node in _of_kind(nodes, "result"):
        result = node.value
        target = _dict(result.get("analysisTarget")).get("uri")
        uris = [_dict(_dict(_dict(location).get("physicalLocation")).get("artifactLocation"))
                .get("uri") for location in _list(result.get("locations"))]
        if target is not None and target in uris:
            yield f"SARIF2004: {node.where}.analysisTarget: repeats the result's location"
        reference = result.get("rule")
        if isinstance(reference, dict):
            component = reference.get("toolComponent")
            to_driver = not isinstance(component, dict) or (
                _index(component.get("index")) == -1 and
                component.get("guid") in (None, _driver(node.run).get("guid")))
            if to_driver:
                yield f"SARIF2004: {node.where}: uses 'rule' where ruleId/ruleIndex suffice"
            elif result.get("ruleId") or _index(result.get("ruleIndex")) >= 0:
                yield f"SARIF2004: {node.where}: has both 'rule' and ruleId/ruleIndex"
    for run in _of_kind(nodes, "run"):
        artifacts = _list(run.value.get("artifacts"))
        results = _list(run.value.get("results"))
        locations = _list(_dict(results[0]).get("locations")) if results else []
        first = _dict(_dict(_dict(locations[0]).get("physicalLocation")).get("artifactLocation")
                      if locations else None)
        if (artifacts and "uri" in first and "index" in first and
                list(_dict(artifacts[0])) == ["location"]):
            yield f"SARIF2004: {run.where}.artifacts: hold nothing but locations"
        rules = _list(_driver(run.value).get("rules"))
        if rules and list(_dict(rules[0])) == ["id"]:
            yield f"SARIF2004: {run.where}.tool.driver.rules: hold nothing but ids"


@multitool_rule("warning")
def SARIF2005_ProvideToolProperties(log, nodes):
    for tool in _of_kind(nodes, "tool"):
        driver = _dict(tool.value.get("driver"))
        where = _where(tool.path + ("driver",))
        name = driver.get("name")
        if isinstance(name, str) and len(name.split()) > 3:
            yield f"SARIF2005: {where}.name: '{name}' is more than three words"
        if driver.get("informationUri") is None:
            yield f"SARIF2005: {where}: no informationUri"
        versions = [driver.get(key)
                    for key in ("version", "semanticVersion", "dottedQuadFileVersion")]
        if not any(isinstance(v, str) and v.strip() for v in versions):
            yield f"SARIF2005: {where}: none of version, semanticVersion, dottedQuadFileVersion"
        version = driver.get("version")
        if isinstance(version, str) and version.strip() and not re.match(r"^\d", version):
            yield f"SARIF2005: {where}.version: '{version}' does not start with a number"


@multitool_rule("warning")
def SARIF2007_ExpressPathsRelativeToRepoRoot(log, nodes):
    for run in _of_kind(nodes, "run"):
        repo_bases = set()
        for i, details in enumerate(_list(run.value.get("versionControlProvenance"))):
            base = _dict(_dict(details).get("mappedTo")).get("uriBaseId")
            if not isinstance(base, str) or not base.strip():
                where = _where(run.path + ("versionControlProvenance", i))
                yield f"SARIF2007: {where}: no mappedTo.uriBaseId"
                continue
            repo_bases.add(base)
            for name, entry in _dict(run.value.get("originalUriBaseIds")).items():
                if _dict(entry).get("uriBaseId") == base:
                    repo_bases.add(name)
        if not repo_bases:
            continue
        for result in _of_kind(nodes, "result"):
            if result.run is not run.value:
                continue
            for i, location in enumerate(_list(result.value.get("locations"))):
                artifact = _dict(_dict(location).get("physicalLocation")).get("artifactLocation")
                if isinstance(artifact, dict) and artifact.get("uriBaseId") not in repo_bases:
                    where = _where(result.path + ("locations", i, "physicalLocation",
                                                  "artifactLocation"))
                    yield (f"SARIF2007: {where}: not relative to a repository root "
                           f"{sorted(repo_bases)}")


@multitool_rule("warning")
def SARIF2008_ProvideSchema(log, nodes):
    if isinstance(log, dict) and "$schema" not in log:
        yield "SARIF2008: (the log): no $schema"


@multitool_rule("warning")
def SARIF2017_ProvideRequiredRegionProperties(log, nodes):
    for node in _of_kind(nodes, "result"):
        for i, location in enumerate(_list(node.value.get("locations"))):
            physical = _dict(location).get("physicalLocation")
            if not isinstance(physical, dict):
                continue
            where = _where(node.path + ("locations", i, "physicalLocation"))
            region = physical.get("region")
            if region is None:
                yield f"SARIF2017: {where}: no region"
            elif not any(_region_kinds(_dict(region)).values()):
                yield f"SARIF2017: {where}.region: has no startLine, charOffset or byteOffset"


def multitool_problems(log):
    """What the Multitool's error- and warning-level rules find in the log."""
    nodes = _sarif_objects(log)
    problems = []
    for _, _, rule in MULTITOOL_RULES:
        problems.extend(rule(log, nodes))
    return problems


def check_sarif(validator, log):
    return _schema_problems(validator, log) + github_problems(log) + multitool_problems(log)


def _good_log():
    """A small log that every check accepts."""
    return {
        "$schema": "https://json.schemastore.org/sarif-2.1.0.json",
        "version": "2.1.0",
        "runs": [{
            "tool": {"driver": {"name": "t", "version": "1.0.0",
                                "informationUri": "https://example.invalid/t",
                                "rules": [{"id": "a/b", "shortDescription": {"text": "d"},
                                           "helpUri": "https://example.invalid/t#a-b"}]}},
            "originalUriBaseIds": {"%SRCROOT%": {"uri": "file:///work/"}},
            "results": [{
                "ruleId": "a/b", "ruleIndex": 0, "level": "error", "message": {"text": "m"},
                "locations": [{"physicalLocation": {
                    "artifactLocation": {"uri": "a.frag", "uriBaseId": "%SRCROOT%"},
                    "region": {"startLine": 1, "startColumn": 1}}}],
            }],
        }],
    }


def _run(log):
    return log["runs"][0]


def _driver_of(log):
    return _run(log)["tool"]["driver"]


def _result(log):
    return _run(log)["results"][0]


def _physical(log):
    return _result(log)["locations"][0]["physicalLocation"]


def _setter(get, key, value):
    return lambda log: get(log).__setitem__(key, value)


def _remover(get, key):
    return lambda log: get(log).pop(key)


# Deliberately broken logs: (what is broken, how, the rule that must say so; None: any check).
BROKEN_LOGS = [
    ("wrong version", _setter(lambda log: log, "version", "2.2.0"), None),
    ("unknown level", _setter(_result, "level", "fatal"), None),
    ("line 0", _setter(lambda log: _physical(log)["region"], "startLine", 0), None),
    ("unknown property", _setter(_result, "severity", "error"), None),
    ("no tool", _remover(_run, "tool"), None),
    ("space in a URI", _setter(_driver_of, "informationUri", "https://example.invalid/a b"), None),
    ("no location", _setter(_result, "locations", []), None),
    # One for each Multitool rule (more where a rule guards against a mistake we could make).
    ("a name equal to the id", _setter(lambda log: _driver_of(log)["rules"][0], "name", "A/B"),
     "SARIF1001"),
    ("'..' in a file URI", _setter(lambda log: _physical(log), "artifactLocation",
                                   {"uri": "file:///work/x/../a.frag"}), "SARIF1002"),
    ("a bad percent escape", _setter(lambda log: _physical(log)["artifactLocation"], "uri",
                                     "a%2.frag"), "SARIF1002"),
    ("uriBaseId with an absolute uri", _setter(lambda log: _physical(log)["artifactLocation"],
                                               "uri", "file:///work/a.frag"), "SARIF1004"),
    ("a base without its final slash",
     _setter(_run, "originalUriBaseIds", {"%SRCROOT%": {"uri": "file:///work"}}), "SARIF1004"),
    ("a relative top-level base", _setter(_run, "originalUriBaseIds",
                                          {"%SRCROOT%": {"uri": "work/"}}), "SARIF1004"),
    ("a relative uri with a leading slash",
     _setter(lambda log: _physical(log)["artifactLocation"], "uri", "/a.frag"), "SARIF1004"),
    ("a relative helpUri", _setter(lambda log: _driver_of(log)["rules"][0], "helpUri",
                                   "docs/rules.md#a-b"), "SARIF1005"),
    ("an invocation that ends before it starts",
     _setter(_run, "invocations", [{"executionSuccessful": True,
                                    "startTimeUtc": "2024-05-02T10:00:00.000Z",
                                    "endTimeUtc": "2024-05-02T09:59:59.000Z"}]), "SARIF1006"),
    ("endLine before startLine", _setter(_physical, "region", {"startLine": 3, "endLine": 2}),
     "SARIF1007"),
    ("endColumn before startColumn", _setter(_physical, "region",
                                             {"startLine": 3, "startColumn": 5, "endColumn": 4}),
     "SARIF1007"),
    ("a contextRegion equal to its region",
     _setter(_physical, "contextRegion", {"startLine": 1, "startColumn": 1}), "SARIF1008"),
    ("a ruleIndex past the rules", _setter(_result, "ruleIndex", 3), "SARIF1009"),
    ("an artifact index without artifacts",
     _setter(lambda log: _physical(log)["artifactLocation"], "index", 0), "SARIF1009"),
    ("no ruleId", lambda log: [_result(log).pop("ruleId"), _result(log).pop("ruleIndex")],
     "SARIF1010"),
    ("a pre-release schema", _setter(lambda log: log, "$schema",
                                     "https://schemastore.azurewebsites.net/schemas/json/"
                                     "sarif-2.1.0-rtm.5.json"), "SARIF1011"),
    ("a message id the rule lacks", _setter(_result, "message", {"id": "default"}), "SARIF1012"),
    ("a sarif: URI that resolves to nothing",
     _setter(lambda log: _physical(log)["artifactLocation"], "uri", "sarif:/runs/3"),
     "SARIF1013"),
    ("a message string without a period",
     _setter(lambda log: _driver_of(log)["rules"][0], "messageStrings",
             {"default": {"text": "no period"}}), "SARIF2001"),
    ("rules that hold only ids", _setter(_driver_of, "rules", [{"id": "a/b"}]), "SARIF2004"),
    ("a sentinel ruleIndex", lambda log: _result(log).update(ruleIndex=-1), "SARIF2004"),
    ("no informationUri", _remover(_driver_of, "informationUri"), "SARIF2005"),
    ("no tool version", _remover(_driver_of, "version"), "SARIF2005"),
    ("a version without a number", _setter(_driver_of, "version", "dev"), "SARIF2005"),
    ("provenance without mappedTo",
     _setter(_run, "versionControlProvenance", [{"repositoryUri": "https://example.invalid/r"}]),
     "SARIF2007"),
    ("no $schema", _remover(lambda log: log, "$schema"), "SARIF2008"),
    ("a location without a region", _remover(_physical, "region"), "SARIF2017"),
]


def self_test(validator):
    """The validator must reject known-bad input before its "valid" means anything."""
    problems = check_sarif(validator, _good_log())
    if problems:
        raise RuntimeError(f"self-test: a valid SARIF log was rejected: {problems}")
    proven = set()
    for name, break_it, rule in BROKEN_LOGS:
        broken = _good_log()
        break_it(broken)
        problems = check_sarif(validator, broken)
        fired = [p for p in problems if rule is None or p.startswith(f"{rule}:")]
        if not fired:
            expected = f"by {rule}" if rule else "at all"
            raise RuntimeError(f"self-test: a broken log ({name}) was not rejected {expected}: "
                               f"{problems}")
        proven.add(rule)
        print(f"self-test: broken SARIF ({name}) rejected: {fired[0]}")
    untested = {rule_id for rule_id, _, _ in MULTITOOL_RULES} - proven
    if untested:
        raise RuntimeError(f"self-test: no broken log for {sorted(untested)}")


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
