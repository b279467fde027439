"""Mutants of real shader stages: one random edit each, drawn from families of token
edits and from insertions aimed at WebGL's own rules (mutation_snippets.py). A seed is
{id, source, stage, context}; a mutant adds {family, edit}. Deterministic for a given
random.Random. Python standard library only.
"""
import json
import os
import re

import mutation_snippets
import shadertoy_reference

_TOKEN = re.compile(r"""
    (?P<comment>//[^\n]*|/\*.*?(?:\*/|\Z))
  | (?P<ws>\s+)
  | (?P<number>(?:\d+\.\d*|\.\d+|\d+)(?:[eE][+-]?\d+)?[a-zA-Z]*|0[xX][0-9a-fA-F]+[uU]?)
  | (?P<ident>[A-Za-z_]\w*)
  | (?P<punct><<=|>>=|\+\+|--|<<|>>|<=|>=|==|!=|&&|\|\||\^\^|\+=|-=|\*=|/=|%=|&=|\^=|\|=|\#\#|.)
""", re.S | re.X)

KEYWORD_CLASSES = [
    "const uniform in out inout attribute varying centroid flat smooth invariant precise".split(),
    "lowp mediump highp superp".split(),
    ("float int uint bool vec2 vec3 vec4 ivec2 ivec3 ivec4 uvec2 uvec3 uvec4 bvec2 bvec3 bvec4 "
     "mat2 mat3 mat4 mat2x3 mat3x2 mat4x3 sampler2D samplerCube sampler3D sampler2DArray "
     "sampler2DShadow isampler2D usampler2D void").split(),
    "if else for while do break continue return discard switch case default".split(),
    ("texture texture2D textureCube texture2DLod textureLod texelFetch textureSize textureGrad "
     "texture2DProj textureProj dFdx dFdy fwidth inverse transpose determinant round roundEven "
     "trunc isnan isinf floatBitsToInt packHalf2x16 sinh tanh modf outerProduct matrixCompMult "
     "lessThan not any all mix step smoothstep sin cos atan pow exp2 mod min max clamp").split(),
    ("gl_FragColor gl_FragData gl_FragCoord gl_FrontFacing gl_PointCoord gl_Position "
     "gl_PointSize gl_VertexID gl_InstanceID gl_FragDepth gl_FragDepthEXT gl_MaxDrawBuffers "
     "gl_DepthRange").split(),
]
_KEYWORD_CLASS = {w: c for c in KEYWORD_CLASSES for w in c}
_BINARY = "+ - * / % < > <= >= == != && || ^^ & | ^ << >> = += -= *= /= %= <<= >>= &= ^= |= , .".split()
_UNARY = "! ~ ++ -- - +".split()
_LITERAL_FORMS = ["1", "1.", ".5", "1e0", "1.0e+0", "1.0f", "1.0F", "01", "0x1", "1u", "1U",
                  "1.0u", "0x1.0", "1e", "1.e2", "1E2", "0.0001", "00.5", "1e-50", "1e50", "08",
                  "0X1A", "0", "0.0", "2147483648", "4294967295", "4294967296", "0xFFFFFFFF",
                  "1.0lf", "1h", "1.5e38", "3.5e38", "1e-45"]
_VERSIONS = ["", "#version 100", "#version 300 es", "#version 300", "#version 310 es",
             "#version 100 es", "#version 200", "#version 300 es // comment", "#version 300es",
             " #version 300 es", "#version 300 ES", "#version 0300 es", "#version 300 es extra",
             "#version", "# version 300 es", "#version 100\n#version 100"]


def tokenize(text):
    return [(m.lastgroup, m.group()) for m in _TOKEN.finditer(text)]


def language(source):
    """'es3' when the first directive is #version 300 es, else 'es1' (what browsers do)."""
    for line in source.splitlines():
        stripped = line.strip()
        if not stripped or stripped.startswith("//"):
            continue
        return "es3" if re.match(r"#\s*version\s+300\s+es\b", stripped) else "es1"
    return "es1"


# --- seeds ------------------------------------------------------------------------------

def load_seeds(shared_dir, project_corpus=None):
    """Conformance stages Chromium compiled, ShaderToy Image passes composed as the site
    composes them, and the project's corpus (WebGL files as they are, ShaderToy files
    wrapped)."""
    seeds = []
    with open(os.path.join(shared_dir, "conformance", "webgl-cts.jsonl"), encoding="utf-8") as f:
        for line in f:
            case = json.loads(line)
            chromium = case.get("chromium") or {}
            for stage, key, ok in (("vertex", "vertex", "vCompiled"), ("fragment", "fragment", "fCompiled")):
                if chromium.get(ok) and case.get(key):
                    seeds.append({"id": "cts:%s:%s" % (case["id"], stage[0]), "source": case[key],
                                  "stage": stage, "context": case.get("contextVersion", 1)})
    with open(os.path.join(shared_dir, "corpus-shadertoy", "permissive.jsonl"), encoding="utf-8") as f:
        for line in f:
            record = json.loads(line)
            try:
                source = shadertoy_reference.compose_record(record)
            except ValueError:
                continue
            seeds.append({"id": "shadertoy:%s" % record["id"], "source": source,
                          "stage": "fragment", "context": 2})
    if project_corpus and os.path.isdir(project_corpus):
        for root, _, files in sorted(os.walk(project_corpus)):
            for name in sorted(files):
                seed = _corpus_seed(os.path.join(root, name), project_corpus)
                if seed:
                    seeds.append(seed)
    return seeds


# The raymarching blog's page (corpus/MANIFEST dialect raymarch-harness, shaderport's
# harness dialect raymarch-blog): what it compiles before the code.
RAYMARCH_PAGE = ("#version 300 es\nprecision highp float;\nin vec2 uv;\nuniform float time;\n"
                 "out vec4 color;\n")


def _manifest_dialects(corpus_dir):
    dialects = {}
    try:
        with open(os.path.join(corpus_dir, "MANIFEST"), encoding="utf-8") as f:
            for line in f.read().splitlines()[1:]:
                fields = line.split("\t")
                if len(fields) == 5:
                    dialects[fields[0]] = fields[2]
    except OSError:
        pass
    return dialects


def _corpus_seed(path, corpus_dir):
    ext = os.path.splitext(path)[1]
    if ext not in (".frag", ".vert", ".glsl"):
        return None
    with open(path, encoding="utf-8", errors="replace") as f:
        source = f.read()
    stage = "vertex" if ext == ".vert" else "fragment"
    dialect = _manifest_dialects(corpus_dir).get(os.path.relpath(path, corpus_dir).replace(os.sep, "/"))
    if dialect == "raymarch-harness":
        # Compiled as its page compiles it, in the browser and by check alike.
        source = RAYMARCH_PAGE + source
    elif re.search(r"\bmainImage\b", source) and not re.search(r"\bvoid\s+main\s*\(", source):
        source = shadertoy_reference.compose_image_pass(source)
    elif ext == ".glsl" and re.search(r"\b(gl_Position|attribute)\b", source):
        stage = "vertex"
    context = 2 if language(source) == "es3" else 1
    return {"id": "corpus:" + os.path.relpath(path, corpus_dir), "source": source,
            "stage": stage, "context": context}


# --- mutation families ------------------------------------------------------------------

def _code_tokens(tokens):
    return [i for i, (kind, _) in enumerate(tokens) if kind not in ("ws", "comment")]


def _join(tokens):
    return "".join(text for _, text in tokens)


def _replace_token(rng, tokens, choose):
    """Replaces one code token for which choose(text) gives a list of candidates."""
    candidates = [i for i in _code_tokens(tokens) if choose(tokens[i])]
    if not candidates:
        return None
    i = rng.choice(candidates)
    new = rng.choice(choose(tokens[i]))
    edit = "token %d %r -> %r" % (i, tokens[i][1], new)
    tokens = list(tokens)
    tokens[i] = ("mut", new)
    return _join(tokens), edit


def delete_token(rng, seed, tokens):
    code = _code_tokens(tokens)
    i = rng.choice(code)
    return _join(tokens[:i] + tokens[i + 1:]), "delete token %d %r" % (i, tokens[i][1])


def duplicate_token(rng, seed, tokens):
    i = rng.choice(_code_tokens(tokens))
    return _join(tokens[:i + 1] + [("ws", " "), tokens[i]] + tokens[i + 1:]), \
        "duplicate token %d %r" % (i, tokens[i][1])


def swap_identifier(rng, seed, tokens):
    names = sorted({t for k, t in tokens if k == "ident" and t not in _KEYWORD_CLASS})
    if len(names) < 2:
        return None
    return _replace_token(rng, tokens, lambda tok: names if tok[0] == "ident" and
                          tok[1] not in _KEYWORD_CLASS else None)


def swap_keyword(rng, seed, tokens):
    return _replace_token(rng, tokens, lambda tok: _KEYWORD_CLASS.get(tok[1]) if tok[0] == "ident" else None)


def literal_form(rng, seed, tokens):
    return _replace_token(rng, tokens, lambda tok: _LITERAL_FORMS if tok[0] == "number" else None)


def operator(rng, seed, tokens):
    def choose(tok):
        if tok[0] != "punct":
            return None
        if tok[1] in ("++", "--", "!", "~"):
            return _UNARY
        return _BINARY if tok[1] in _BINARY else None
    return _replace_token(rng, tokens, choose)


def version_line(rng, seed, tokens):
    lines = seed["source"].split("\n")
    new = rng.choice(_VERSIONS)
    first = next((i for i, l in enumerate(lines) if l.strip().startswith("#version")), None)
    where = rng.choice(["replace", "replace", "move", "prepend-comment", "prepend-blank"])
    if first is None or where == "replace":
        if first is None:
            lines.insert(0, new)
        else:
            lines[first] = new
        return "\n".join(lines), "version %r (%s)" % (new, "replace" if first is not None else "add")
    line = lines.pop(first)
    if where == "move":
        at = rng.randrange(first + 1, len(lines) + 1) if len(lines) > first else first
        lines.insert(at, line)
        return "\n".join(lines), "version line moved to line %d" % (at + 1)
    lines.insert(first, line)
    lines.insert(first, "// comment" if where == "prepend-comment" else "")
    return "\n".join(lines), "version line after a %s" % where.split("-")[1]


def line_edit(rng, seed, tokens):
    lines = seed["source"].split("\n")
    i = rng.randrange(len(lines))
    kind = rng.choice(["delete", "duplicate", "swap", "move-directive"])
    if kind == "delete":
        del lines[i]
    elif kind == "duplicate":
        lines.insert(i, lines[i])
    elif kind == "swap" and i + 1 < len(lines):
        lines[i], lines[i + 1] = lines[i + 1], lines[i]
    else:
        directives = [j for j, l in enumerate(lines) if l.lstrip().startswith("#")]
        if not directives:
            return None
        j = rng.choice(directives)
        line = lines.pop(j)
        i = rng.randrange(len(lines) + 1)
        lines.insert(i, line)
        return "\n".join(lines), "directive line %d moved to %d" % (j + 1, i + 1)
    return "\n".join(lines), "%s line %d" % (kind, i + 1)


def _function_bodies(tokens):
    """Token indices just after a function body's '{', and of ';' at statement level."""
    starts, semis = [], []
    depth = paren = 0
    previous = None
    for i, (kind, text) in enumerate(tokens):
        if kind in ("ws", "comment"):
            continue
        if text == "(":
            paren += 1
        elif text == ")":
            paren -= 1
        elif text == "{":
            if depth == 0 and previous == ")":
                starts.append(i + 1)
            depth += 1
        elif text == "}":
            depth = max(0, depth - 1)
        elif text == ";" and depth > 0 and paren == 0:
            semis.append(i + 1)
        previous = text
    return starts, semis


def _global_points(source):
    """Line numbers (0-based, insert before) between top-level declarations: after the
    #version line, after each top-level ';' or '}' that ends a line, at the end."""
    lines = source.split("\n")
    points = []
    depth = 0
    for i, line in enumerate(lines):
        stripped = line.strip()
        if stripped.startswith("#"):
            if depth == 0 and not line.rstrip().endswith("\\"):
                points.append(i + 1)
            continue
        code = re.sub(r"//.*", "", line)
        depth += code.count("{") - code.count("}")
        if depth == 0 and (stripped.endswith(";") or stripped.endswith("}")):
            points.append(i + 1)
    points.append(len(lines))
    return sorted(set(points))


def insert_snippet(rng, seed, tokens, topic=None):
    lang = language(seed["source"])
    topic = topic or rng.choice(sorted(mutation_snippets.TOPICS))
    fitting = [s for s in mutation_snippets.TOPICS[topic]
               if (s[2] == "*" or lang in s[2]) and (s[3] == "*" or seed["stage"] in s[3])]
    if not fitting:
        return None
    where, text, _, _ = rng.choice(fitting)
    global_part, statement_part = (text, None) if where == "global" else (None, text)
    if " ||| " in text:
        global_part, statement_part = text.split(" ||| ", 1)
    source = seed["source"]
    if statement_part is not None:
        starts, semis = _function_bodies(tokens)
        points = starts + semis
        if not points:
            return None
        at = rng.choice(points)
        if "\n" in statement_part and not statement_part.startswith("\n"):
            statement_part = "\n" + statement_part + "\n"
        source = _join(tokens[:at]) + " " + statement_part + " " + _join(tokens[at:])
    if global_part is not None:
        lines = source.split("\n")
        points = _global_points(source)
        if statement_part is not None:  # declarations before their use
            first_body = len(_join(tokens[:_function_bodies(tokens)[0][0]]).split("\n")) \
                if _function_bodies(tokens)[0] else len(lines)
            points = [p for p in points if p < first_body] or [0]
        at = rng.choice(points)
        lines.insert(at, global_part)
        source = "\n".join(lines)
    return source, "insert %s: %s" % (topic, text[:160].replace("\n", "\\n"))


FAMILIES = {
    "delete-token": delete_token,
    "duplicate-token": duplicate_token,
    "swap-identifier": swap_identifier,
    "swap-keyword": swap_keyword,
    "literal-form": literal_form,
    "operator": operator,
    "version": version_line,
    "line": line_edit,
    "insert": insert_snippet,
}
# Insertions carry most of WebGL's own rules: they get half of the draws.
FAMILY_WEIGHTS = {"insert": 9}


def mutate(rng, seed):
    """One mutant of `seed`, or None when the drawn family does not apply."""
    names = sorted(FAMILIES)
    weights = [FAMILY_WEIGHTS.get(n, 1) for n in names]
    family = rng.choices(names, weights)[0]
    tokens = tokenize(seed["source"])
    if not _code_tokens(tokens):
        return None
    result = FAMILIES[family](rng, seed, tokens)
    if result is None or result[0] == seed["source"]:
        return None
    return {"seed": seed["id"], "source": result[0], "stage": seed["stage"],
            "context": seed["context"], "family": family, "edit": result[1]}
