#!/usr/bin/env python3
"""Fails when docs/config.md or docs/network_model.md says something else than the code about the
network's keys and models.

1. Keys. The `network.*` keys the config reader accepts are read from its source
   (experiments/config/*.cpp, comments removed), starting at ReadExperiment on the config's root:
   a function that takes a `const Field& f` reads the keys its `f.ExpectMap({"a", "b"})` lists at
   its own level; `x.Child("k")` is one level down, passed on directly
   (`ReadLoss(f.Child("loss"))`) or through a variable (`const Field c = f.Child("routing");`,
   `auto c = ...`), and `for (const Field& item : x.Items())` is x's level (a list's items: the
   docs write `network.links[i].src`, read here as `network.links.src`). A function that hands its
   `std::initializer_list` parameter to ExpectMap (ReadKindOrMap) reads the `{"kind", ...}` its
   caller passes; a reader passed as an argument (`ReadList<double>(range, ReadRange)`) reads at
   that argument's level.
   docs/config.md documents a key in the "Keys" table: in a row's first cell (`.dst` after
   `network.links[i].src` is `network.links[i].dst`), or as a key of a `{key: value, key}` map in
   the row of the key above it (`{model: bernoulli, p}` in `network.loss`'s row); a row whose
   cell begins "as `X`" documents X's keys under its own (`network.links[i].loss`: as
   `network.loss`). A map whose keys have rows of their own needs none (`network.radio.log_distance`).
   Refused: a key the reader accepts that the table does not document, and one the table
   documents that the reader does not accept.
2. Models. The names `network.model` accepts are the reader's table of spellings (kNames in
   net_models/helper/link_factory.cpp); the models that contend are those Contends() lists there.
   docs/network_model.md's table under "Link models at a glance" has one row per model, no
   other, and its `contention` cell begins "yes" exactly for the models that contend; the
   `network.model` row of docs/config.md names every model.

Usage: scripts/check_docs.py [REPO_ROOT]    exit 0: clean, 1: the docs disagree, 2: cannot read
"""
import pathlib
import re
import sys

from check_protocol_names import without_comments

ROOT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).resolve().parent.parent)
READER_DIR = "experiments/config"
ROOT_READER = "ReadExperiment"
SECTION = "network"
CONFIG_DOC = "docs/config.md"
KEYS_HEADING = "Keys"
MODEL_NAMES = "net_models/helper/link_factory.cpp"
MODEL_DOC = "docs/network_model.md"
MODELS_HEADING = "Link models at a glance"

KEYWORDS = {"if", "for", "while", "switch", "catch", "return", "sizeof", "decltype", "static_assert"}
NAME_AND_PAREN = re.compile(r"\b(\w+)\s*\(")
FIELD_PARAM = re.compile(r"\bconst\s+Field\s*&\s*(\w+)")
KEYS_PARAM = re.compile(r"\binitializer_list\s*<\s*std::string_view\s*>\s*(\w+)")
CHILD_BINDING = re.compile(r'\b(?:const\s+)?(?:Field|auto)\s+(\w+)\s*=\s*(\w+)\.Child\("([^"]*)"\)')
ITEMS_BINDING = re.compile(r"\bconst\s+Field\s*&\s*(\w+)\s*:\s*(\w+)\.Items\(\)")
EXPECT_LIST = re.compile(r"\b(\w+)\.ExpectMap\(\s*\{([^{}]*)\}\s*\)")
EXPECT_PARAM = re.compile(r"\b(\w+)\.ExpectMap\(\s*(\w+)\s*\)")
STRING_LIST = re.compile(r'^\{\s*"[^"]*"(?:\s*,\s*"[^"]*")*\s*\}$')
FIELD_ARG = re.compile(r'^(\w+)(?:\.Child\("([^"]*)"\))?')
MODEL_NAME = re.compile(r'\{\s*LinkModelKind::(k\w+)\s*,\s*"([^"]+)"\s*\}')
CONTENDS = re.compile(r"\bbool\s+Contends\s*\(\s*LinkModelKind\s+(\w+)\s*\)\s*\{\s*return\s+([^;]*);")


class CannotRead(Exception):
    pass


# ---------------------------------------------------------------- the config reader's keys

def skip_literal(text, i):
    """The index after the string or character literal that starts at text[i]."""
    quote, j = text[i], i + 1
    while j < len(text) and text[j] != quote:
        j += 2 if text[j] == "\\" else 1
    return j + 1


def matching(text, i):
    """The index after the bracket that closes the one at text[i], literals skipped."""
    close = {"(": ")", "{": "}", "[": "]"}[text[i]]
    depth, j = 0, i
    while j < len(text):
        c = text[j]
        if c in "\"'":
            j = skip_literal(text, j)
            continue
        if c == text[i]:
            depth += 1
        elif c == close:
            depth -= 1
            if depth == 0:
                return j + 1
        j += 1
    raise CannotRead(f"unbalanced {text[i]} in the config reader")


def split_arguments(text):
    """The top-level comma-separated parts of an argument or parameter list, stripped."""
    parts, start, i = [], 0, 0
    while i < len(text):
        c = text[i]
        if c in "\"'":
            i = skip_literal(text, i)
            continue
        if c in "({[":
            i = matching(text, i)
            continue
        if c == ",":
            parts.append(text[start:i].strip())
            start = i + 1
        i += 1
    last = text[start:].strip()
    return parts + [last] if last else parts


def reader_functions():
    """name -> list of (file, (index, name) of its Field parameter, index of the initializer_list
    parameter it hands to that Field's ExpectMap or None, body): every function of the reader's
    files that takes a `const Field&`."""
    functions = {}
    for path in sorted((ROOT / READER_DIR).glob("*.cpp")):
        text = without_comments(path.read_text())
        rel = path.relative_to(ROOT).as_posix()
        i = 0
        while True:
            m = NAME_AND_PAREN.search(text, i)
            if not m:
                break
            name, open_paren = m.group(1), m.end() - 1
            close = matching(text, open_paren)
            tail = re.match(r"\s*(?:const\s*)?(?:noexcept\s*)?(?:->[^;{]*)?\{", text[close:])
            if name in KEYWORDS or not tail:
                i = m.end()
                continue
            body_start = close + tail.end() - 1
            body_end = matching(text, body_start)
            params = split_arguments(text[open_paren + 1:close - 1])
            field = next(((k, FIELD_PARAM.search(p).group(1)) for k, p in enumerate(params)
                          if FIELD_PARAM.search(p)), None)
            body = text[body_start:body_end]
            forwarded = {m.group(2) for m in EXPECT_PARAM.finditer(body) if field and m.group(1) == field[1]}
            keys = next((k for k, p in enumerate(params)
                         if KEYS_PARAM.search(p) and KEYS_PARAM.search(p).group(1) in forwarded), None)
            if field is not None:
                functions.setdefault(name, []).append((rel, field, keys, body))
            i = body_end
    return functions


def bindings(body, field_name, path):
    """(position, variable, path) of the Field variables of a body, in order: the parameter, then
    each `Field v = x.Child("k")` and `for (const Field& v : x.Items())`. A variable means the path
    of its latest binding before a use (None: not a key of the config)."""
    found = [(m.start(), m.group(1), m.group(2), (m.group(3),)) for m in CHILD_BINDING.finditer(body)]
    found += [(m.start(), m.group(1), m.group(2), ()) for m in ITEMS_BINDING.finditer(body)]
    resolved = [(0, field_name, path)]
    for pos, var, parent, below in sorted(found):
        base = path_at(resolved, parent, pos)
        resolved.append((pos, var, None if base is None else base + below))
    return resolved


def path_at(resolved, var, pos):
    path = None
    for p, v, where in resolved:
        if p <= pos and v == var:
            path = where
    return path


def argument_path(resolved, arg, pos):
    m = FIELD_ARG.match(arg)
    if not m:
        return None
    base = path_at(resolved, m.group(1), pos)
    if base is None:
        return None
    return base + (m.group(2),) if m.group(2) is not None else base


def reader_keys():
    """dotted key -> "file: Function" of the ExpectMap that accepts it, for the whole config."""
    functions = reader_functions()
    if ROOT_READER not in functions:
        raise CannotRead(f"{READER_DIR}/*.cpp: no {ROOT_READER}(const Field& ...) to start from")
    call = re.compile(r"\b(?:\w+::)*(" + "|".join(map(re.escape, functions)) + r")\s*(?:<[^<>;()]*>)?\s*\(")
    keys, seen, todo = {}, set(), [(ROOT_READER, ())]
    while todo:
        name, path = todo.pop()
        if (name, path) in seen:
            continue
        seen.add((name, path))
        for rel, (_, field_name), _, body in functions[name]:
            resolved = bindings(body, field_name, path)
            where = f"{rel}: {name}"
            for m in EXPECT_LIST.finditer(body):
                level = path_at(resolved, m.group(1), m.start())
                for key in re.findall(r'"([^"]*)"', m.group(2)):
                    if level is not None:
                        keys.setdefault(".".join(level + (key,)), where)
            for m in call.finditer(body):
                callee = m.group(1)
                args = split_arguments(body[m.end():matching(body, m.end() - 1) - 1])
                for _, (field_index, _), keys_index, _ in functions[callee]:
                    if field_index >= len(args):
                        continue
                    level = argument_path(resolved, args[field_index], m.start())
                    if level is None:
                        continue
                    todo.append((callee, level))
                    if keys_index is not None and keys_index < len(args) and STRING_LIST.match(args[keys_index]):
                        for key in re.findall(r'"([^"]*)"', args[keys_index]):
                            keys.setdefault(".".join(level + (key,)), f"{rel}: {name} through {callee}")
                    for arg in args:
                        if arg in functions and arg != callee:
                            todo.append((arg, level))
    return keys


# ---------------------------------------------------------------- the docs' tables

def table_under(text, heading, doc):
    """The rows (lists of cells) of the first table under the heading `heading` (any level),
    header row included."""
    m = re.search(r"^#+ " + re.escape(heading) + r"\s*$", text, re.M)
    if not m:
        raise CannotRead(f"{doc}: no '{heading}' section")
    rows, started = [], False
    for line in text[m.end():].splitlines()[1:]:
        if line.startswith("#"):
            break
        if not line.startswith("|"):
            if started:
                break
            continue
        started = True
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if set("".join(cells)) <= {"-", " ", ":"}:
            continue
        rows.append(cells)
    if not rows:
        raise CannotRead(f"{doc}: no table under '{heading}'")
    return rows


def backticked(cell):
    return re.findall(r"`([^`]+)`", cell)


def normal(key):
    return re.sub(r"\[\w*\]", "", key)


def map_keys(cell):
    """The keys of each `{key: value, key}` map written in a cell."""
    keys = []
    for inner in re.findall(r"\{([^{}]*)\}", cell):
        entries = [e.strip() for e in inner.split(",")]
        names = [re.match(r"^(\w+)(?:\s*:\s*\S.*)?$", e) for e in entries]
        if all(names):
            keys.extend(n.group(1) for n in names)
    return keys


def documented_keys():
    """(rows: key -> the row's text for its own key and the map keys in the row of the key
    above; aliases: key -> the key it is documented as; the network.model row's accepts cell)."""
    text = (ROOT / CONFIG_DOC).read_text()
    rows, aliases, model_cell = {}, {}, None
    for cells in table_under(text, KEYS_HEADING, CONFIG_DOC)[1:]:
        if len(cells) < 2:
            continue
        row_keys, previous = [], None
        for k in backticked(cells[0]):
            if k.startswith(".") and previous is not None:
                k = previous.rsplit(".", 1)[0] + k
            previous = k
            row_keys.append(normal(k))
        for k in row_keys:
            if not k.startswith(SECTION + "."):
                continue
            rows[k] = f"its row ({cells[0]})"
            for child in map_keys(cells[1]):
                rows.setdefault(f"{k}.{child}", f"a key of the map in the row of {k}")
            alias = re.match(r"as\s+`([^`]+)`", cells[1])
            if alias:
                aliases[k] = normal(alias.group(1))
            if k == SECTION + ".model":
                model_cell = cells[1]
    return rows, aliases, model_cell


def key_problems(accepted, rows, aliases):
    problems = []
    documented = set(rows)
    for key, target in aliases.items():
        documented |= {key + d[len(target):] for d in rows if d.startswith(target + ".")}
    for key in sorted(accepted):
        if not key.startswith(SECTION + "."):
            continue
        if key not in documented and not any(d.startswith(key + ".") for d in documented):
            problems.append(f"{CONFIG_DOC}: {key}: the config reader accepts it ({accepted[key]}), "
                            f"the Keys table does not document it")
    for key in sorted(rows):
        if "*" in key:
            problems.append(f"{CONFIG_DOC}: {key}: name the {SECTION} keys one by one, not with *")
        elif key not in accepted:
            problems.append(f"{CONFIG_DOC}: {key}: documented ({rows[key]}), but the config reader "
                            f"({READER_DIR}/*.cpp) does not accept it")
    return problems


def code_models():
    """(model name -> whether it contends), from the spellings table and Contends()."""
    text = without_comments((ROOT / MODEL_NAMES).read_text())
    kinds = dict(MODEL_NAME.findall(text))
    if not kinds:
        raise CannotRead(f"{MODEL_NAMES}: no {{LinkModelKind::k..., \"name\"}} spellings")
    m = CONTENDS.search(text)
    if not m:
        raise CannotRead(f"{MODEL_NAMES}: no 'bool Contends(LinkModelKind kind) {{ return ...; }}'")
    var, terms = m.group(1), [t.strip() for t in m.group(2).split("||")]
    contending = set()
    for t in terms:
        k = re.fullmatch(rf"{var}\s*==\s*LinkModelKind::(k\w+)", t)
        if not k or k.group(1) not in kinds:
            raise CannotRead(f"{MODEL_NAMES}: Contends() is not 'kind == LinkModelKind::k... || ...' "
                             f"(got '{m.group(2)}'): teach scripts/check_docs.py to read it")
        contending.add(kinds[k.group(1)])
    return {name: name in contending for name in kinds.values()}


def model_problems(models, model_cell):
    problems = []
    rows = table_under((ROOT / MODEL_DOC).read_text(), MODELS_HEADING, MODEL_DOC)
    header = [c.lower() for c in rows[0]]
    if not header or header[0] != "model" or "contention" not in header:
        raise CannotRead(f"{MODEL_DOC}: the table under '{MODELS_HEADING}' needs the columns model, ..., contention")
    column = header.index("contention")
    table = {}
    for cells in rows[1:]:
        names = backticked(cells[0])
        name = names[0] if names else cells[0]
        table[name] = cells[column] if column < len(cells) else ""
    for name, contends in sorted(models.items()):
        if name not in table:
            problems.append(f"{MODEL_DOC}: {name}: network.model accepts it ({MODEL_NAMES}), "
                            f"the table under '{MODELS_HEADING}' has no row for it")
            continue
        said = table[name].split()[0].strip(":,;").lower() if table[name].split() else ""
        if said != ("yes" if contends else "no"):
            problems.append(f"{MODEL_DOC}: {name}: its contention cell says '{table[name]}', but "
                            f"Contends() ({MODEL_NAMES}) says it {'does' if contends else 'does not'} contend: "
                            f"begin the cell with {'yes' if contends else 'no'}")
    for name in sorted(set(table) - set(models)):
        problems.append(f"{MODEL_DOC}: {name}: a row under '{MODELS_HEADING}', but network.model "
                        f"accepts no such model ({MODEL_NAMES})")
    if model_cell is None:
        problems.append(f"{CONFIG_DOC}: {SECTION}.model: no row in the Keys table")
    else:
        for name in sorted(set(models) - set(backticked(model_cell))):
            problems.append(f"{CONFIG_DOC}: {SECTION}.model: its row does not name the model `{name}`, "
                            f"which network.model accepts ({MODEL_NAMES})")
    return problems


def main():
    try:
        accepted = reader_keys()
        if not any(k.startswith(SECTION + ".") for k in accepted):
            raise CannotRead(f"{READER_DIR}/*.cpp: found no {SECTION}.* key from {ROOT_READER}")
        rows, aliases, model_cell = documented_keys()
        models = code_models()
        problems = key_problems(accepted, rows, aliases) + model_problems(models, model_cell)
    except (CannotRead, OSError) as e:
        print(f"check_docs: {e}", file=sys.stderr)
        return 2
    for p in problems:
        print(p, file=sys.stderr)
    if problems:
        print(f"check_docs: {len(problems)} place(s) where the docs disagree with the code", file=sys.stderr)
        return 1
    network = sum(k.startswith(SECTION + ".") for k in accepted)
    print(f"check_docs: {CONFIG_DOC} documents the {network} {SECTION}.* keys the reader accepts, and "
          f"{MODEL_DOC} the {len(models)} models and which contend")
    return 0


if __name__ == "__main__":
    sys.exit(main())
