#!/usr/bin/env python3
"""Fails when src/ or rules/ declares its own shader stage, WebGL target, channel kind
or pass kind: src/model/ holds the one definition of each (issue 28), so that no layer
needs a function converting its copy into another layer's.

An enum outside src/model/ is refused when its name is one that these concepts went
by, or when its enumerators are those of a model enum (an "unspecified" value such as
kAuto aside: that is std::optional of the model type).
"""
import pathlib
import re
import sys

MODEL_ENUMS = ("Stage", "Target", "ChannelKind", "PassKind")
FORMER_NAMES = {"Stage", "ShaderStage", "Target", "WebglTarget", "ChannelKind", "ChannelType",
                "PassKind", "PassType", "ShaderToyPass"}
UNSPECIFIED = {"kAuto", "kNone", "kUnknown", "kDefault", "kUnspecified"}

ENUM = re.compile(r"\benum\s+(?:class|struct)?\s*(\w+)\s*(?::\s*[\w:]+\s*)?\{([^}]*)\}")
COMMENT = re.compile(r"//[^\n]*|/\*.*?\*/", re.S)


def enums_in(path):
    text = COMMENT.sub("", path.read_text(encoding="utf-8", errors="replace"))
    for match in ENUM.finditer(text):
        names = frozenset(e.split("=")[0].strip() for e in match.group(2).split(",")
                          if e.strip())
        yield match.group(1), names, text.count("\n", 0, match.start()) + 1


def sources(root, *dirs):
    for d in dirs:
        for path in sorted((root / d).rglob("*")):
            if path.suffix in (".h", ".cpp") and path.is_file():
                yield path


def main():
    root = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else ".").resolve()
    model_dir = root / "src" / "model"
    model = {}
    if model_dir.is_dir():
        for path in sources(root, "src/model"):
            for name, enumerators, _ in enums_in(path):
                model[name] = enumerators
    failures = [f"src/model/ declares no enum {name}" for name in MODEL_ENUMS if name not in model]
    model_sets = {enumerators: name for name, enumerators in model.items()}
    for path in sources(root, "src", "rules"):
        if model_dir in path.parents:
            continue
        for name, enumerators, line in enums_in(path):
            where = f"{path.relative_to(root)}:{line}: enum {name}"
            same_as = model_sets.get(enumerators) or model_sets.get(enumerators - UNSPECIFIED)
            if name in FORMER_NAMES:
                failures.append(f"{where} is declared outside src/model/")
            elif same_as:
                failures.append(f"{where} repeats model::{same_as}'s enumerators")
    for failure in failures:
        print("one_model: " + failure + " (use the type in src/model/)", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
