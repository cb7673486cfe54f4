"""Deterministic boundary fuzzer: every POST calculation at the edges of its valid inputs.

Schemathesis draws random cases; this draws the ones at the edges, the same ones every run.
For every POST operation in `openapi/openapi.json` it starts from the operation's example body
and, one field at a time (nested objects and array items too), substitutes edge values: the
schema's minimum and maximum, values just inside and just outside them (x(1 ± 1e-12), the next
float), 0, 5e-324, 1e-300, 1e300, -1; each enum value and each `oneOf` alternative with an
example; an optional field the example leaves out, at its example and its edges. Then pairs:
every two numeric fields in the same unit set equal (inlet = outlet film, inner = outer radius,
min = max), and every two numeric fields at (min, min), (min, max), (max, min), (max, max), an
exclusive minimum of 0 taken as the smallest normal double.

`--quick` (about 10 600 cases, 65 s against the debug server) keeps the examples without
the (min, max) pairs. The full run (about 47 000 cases, 6 minutes) adds them, starts also from
each README curl body, and fills each optional object the example leaves out (effects,
dynamics, a custom fidelity, another viscosity law: the siblings it conflicts with dropped,
and a body the server still refuses is skipped) to vary its fields one at a time;
`--data` starts also from each reference case in tests/data, one field at a time (about
89 000 cases in all, 9 minutes).

Each case goes to a running server (`STRIBECK_ADDR=127.0.0.1:18090 ./target/debug/stribeck serve`)
with `x-stribeck-deadline-ms` (20 000 by default) and a client timeout of 30 s. A failure is a 5xx
(a 504 only when it overran the deadline by more than 2 s), a connection failure or timeout, or a
response holding a number that is not finite (NaN, Infinity). Failures are printed as one JSON
line each (path, status, the field(s) changed, the body); the server's log (`cause=`) says why.
The exit code is 1 if any occurred.

    python3 scripts/edge_fuzz.py [--base http://127.0.0.1:18090] [--quick] [--data]
                                 [--only SUBSTRING] [--jobs 2] [--deadline-ms 20000] [--list]
"""

import argparse
import concurrent.futures
import copy
import itertools
import json
import math
import re
import sys
import time
import urllib.error
import urllib.request
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def resolve(spec, schema):
    """Follow `$ref`s; merge a lone `allOf`; return {} for None."""
    seen = 0
    while isinstance(schema, dict) and "$ref" in schema and seen < 50:
        name = schema["$ref"].rsplit("/", 1)[-1]
        schema = spec["components"]["schemas"][name]
        seen += 1
    if isinstance(schema, dict) and "allOf" in schema and len(schema["allOf"]) == 1:
        return resolve(spec, schema["allOf"][0])
    return schema or {}


def alternatives(spec, schema):
    """The non-null alternatives of a oneOf/anyOf (or the schema itself)."""
    schema = resolve(spec, schema)
    alts = schema.get("oneOf") or schema.get("anyOf")
    if not alts:
        return [schema]
    out = []
    for a in alts:
        r = resolve(spec, a)
        if r.get("type") == "null":
            continue
        out.extend(alternatives(spec, r) if ("oneOf" in r or "anyOf" in r) else [r])
    return out


def types_of(schema):
    t = schema.get("type")
    if t is None:
        return set()
    return set(t) if isinstance(t, list) else {t}


def next_up(x):
    return math.nextafter(x, math.inf)


def next_down(x):
    return math.nextafter(x, -math.inf)


def numeric_edges(schema):
    """Edge values for a number or integer schema, each with a label."""
    integer = "integer" in types_of(schema)
    lo, hi = schema.get("minimum"), schema.get("maximum")
    xlo, xhi = schema.get("exclusiveMinimum"), schema.get("exclusiveMaximum")
    vals = []
    if integer:
        for b, name in ((lo, "min"), (hi, "max")):
            if b is not None:
                vals += [(b, name), (b - 1, name + "-1"), (b + 1, name + "+1")]
        for b, name in ((xlo, "xmin"), (xhi, "xmax")):
            if b is not None:
                vals += [(b, name), (b + 1, name + "+1"), (b - 1, name + "-1")]
        vals += [(0, "zero"), (1, "one"), (-1, "minus_one"), (2**31 - 1, "i32max"), (2**53, "2^53")]
    else:
        for b, name in ((lo, "min"), (hi, "max"), (xlo, "xmin"), (xhi, "xmax")):
            if b is None:
                continue
            vals += [(b, name), (next_up(b), name + "+ulp"), (next_down(b), name + "-ulp")]
            if b != 0:
                vals += [(b * (1 + 1e-12), name + "*(1+1e-12)"), (b * (1 - 1e-12), name + "*(1-1e-12)")]
            else:
                vals += [(1e-300, name + "+1e-300"), (-1e-300, name + "-1e-300")]
        vals += [(0.0, "zero"), (1e-300, "tiny"), (1e300, "huge"), (-1.0, "minus_one"),
                 (-1e300, "-huge"), (5e-324, "denormal")]
    seen, out = set(), []
    for v, name in vals:
        key = (type(v), v)
        if key not in seen:
            seen.add(key)
            out.append((v, name))
    return out


def bound(schema, which):
    """The inclusive (or just-inside exclusive) bound, or None."""
    integer = "integer" in types_of(schema)
    if which == "min":
        if schema.get("minimum") is not None:
            return schema["minimum"]
        if schema.get("exclusiveMinimum") is not None:
            b = schema["exclusiveMinimum"]
            if integer:
                return b + 1
            # Above 0, the smallest normal double: the server refuses subnormals at the door.
            return sys.float_info.min if b == 0 else b * (1 + 1e-12) if b > 0 else b * (1 - 1e-12)
    else:
        if schema.get("maximum") is not None:
            return schema["maximum"]
        if schema.get("exclusiveMaximum") is not None:
            b = schema["exclusiveMaximum"]
            return b - 1 if integer else b * (1 - 1e-12) if b > 0 else b * (1 + 1e-12)
    return None


def example_of(spec, schema):
    """A value for a schema: its example, else one built from its properties' examples."""
    schema = resolve(spec, schema)
    if "example" in schema:
        return copy.deepcopy(schema["example"])
    if "enum" in schema:
        return schema["enum"][0]
    alts = alternatives(spec, schema)
    if alts and alts[0] is not schema:
        return example_of(spec, alts[0])
    t = types_of(schema) - {"null"}
    if "object" in t or "properties" in schema:
        obj = {}
        for name in schema.get("required", []):
            v = example_of(spec, schema["properties"].get(name, {}))
            if v is not None:
                obj[name] = v
        return obj
    if "array" in t:
        item = example_of(spec, schema.get("items", {}))
        return [item] * max(1, schema.get("minItems", 1)) if item is not None else []
    if t & {"number", "integer"}:
        b = bound(schema, "min")
        return b if b is not None else 1
    if "boolean" in t:
        return False
    return None


class Slot:
    """One place in a body: a JSON pointer (as a path list) and the schema that governs it."""

    def __init__(self, path, schema, present):
        self.path, self.schema, self.present = path, schema, present

    @property
    def pointer(self):
        return "/" + "/".join(str(p) for p in self.path)


def walk(spec, schema, value, path, out, depth=0):
    """Collect slots for every leaf under `value` and every optional property it leaves out."""
    if depth > 8:
        return
    alts = alternatives(spec, schema)
    # The alternative that the present value fits (by JSON type), else the first.
    chosen = alts[0] if alts else {}
    for a in alts:
        t = types_of(a) - {"null"}
        if isinstance(value, dict) and ("object" in t or "properties" in a):
            chosen = a
            break
        if isinstance(value, str) and ("string" in t or "enum" in a):
            chosen = a
            break
        if isinstance(value, bool) and "boolean" in t:
            chosen = a
            break
        if isinstance(value, (int, float)) and not isinstance(value, bool) and t & {"number", "integer"}:
            chosen = a
            break
        if isinstance(value, list) and "array" in t:
            chosen = a
            break
    out.append(Slot(path, schema, value is not None))
    if isinstance(value, dict):
        props = chosen.get("properties", {})
        for name, sub in props.items():
            if name in value:
                walk(spec, sub, value[name], path + [name], out, depth + 1)
            else:
                out.append(Slot(path + [name], sub, False))
    elif isinstance(value, list):
        items = chosen.get("items", {})
        for i, v in enumerate(value[:4]):
            walk(spec, items, v, path + [i], out, depth + 1)


def get_at(body, path):
    for p in path:
        body = body[p]
    return body


def set_at(body, path, value):
    target = body
    for p in path[:-1]:
        target = target[p]
    target[path[-1]] = value


def leaf_numeric(spec, schema):
    """The numeric alternative of a slot's schema, or None."""
    for a in alternatives(spec, schema):
        if types_of(a) & {"number", "integer"}:
            return a
    return None


def variants(spec, slot, base):
    """(label, value) substitutions for one slot."""
    out = []
    num = leaf_numeric(spec, slot.schema)
    if num is not None:
        out += [(name, v) for v, name in numeric_edges(num)]
    for a in alternatives(spec, slot.schema):
        if "enum" in a:
            out += [("enum=" + str(e), e) for e in a["enum"]]
        elif "boolean" in types_of(a):
            out += [("true", True), ("false", False)]
        elif "string" in types_of(a):
            out += [("empty_string", "")]
        elif types_of(a) & {"object"} or "properties" in a:
            ex = example_of(spec, a)
            if ex is not None and (not slot.present or ex != get_at(base, slot.path)):
                out.append(("alt:" + str(a.get("description", "object"))[:30], ex))
        elif "array" in types_of(a):
            if slot.present:
                cur = get_at(base, slot.path)
                out += [("empty_array", [])]
                if isinstance(cur, list) and cur:
                    out += [("one_item", cur[:1]), ("many_items", cur * 8)]
            else:
                ex = example_of(spec, a)
                if ex is not None:
                    out.append(("example", ex))
    if not slot.present:
        ex = example_of(spec, slot.schema)
        if ex is not None:
            out.insert(0, ("example", ex))
    return out


UNIT = re.compile(r"_(m|m_s|n|pa|pa_s|rpm|c|k|deg|rad|s|hz|m3_s|w|kg_m3|1_pa|mm2_s|fraction|n_m|kg|j_kg_k|rad_s)$")


def unit_of(path):
    name = next((p for p in reversed(path) if isinstance(p, str)), "")
    m = UNIT.search(name)
    return m.group(1) if m else None


def cases_for(spec, path, base, quick):
    """Every (label, body) case for one base body."""
    op = spec["paths"][path]["post"]
    schema = op["requestBody"]["content"]["application/json"]["schema"]
    slots = []
    walk(spec, schema, base, [], slots)
    slots = [s for s in slots if s.path]
    cases = []
    for slot in slots:
        for label, v in variants(spec, slot, base):
            body = copy.deepcopy(base)
            try:
                set_at(body, slot.path, v)
            except (KeyError, IndexError, TypeError):
                continue
            cases.append((f"{slot.pointer}={label}", body))
    numeric = [s for s in slots if s.present and leaf_numeric(spec, s.schema) is not None
               and isinstance(get_at(base, s.path), (int, float))]
    for a, b in itertools.combinations(numeric, 2):
        ua, ub = unit_of(a.path), unit_of(b.path)
        if ua is not None and ua == ub:
            for x, y in ((a, b), (b, a)):
                body = copy.deepcopy(base)
                set_at(body, x.path, get_at(base, y.path))
                cases.append((f"{x.pointer}=={y.pointer}", body))
        if quick:
            continue
        sa, sb = leaf_numeric(spec, a.schema), leaf_numeric(spec, b.schema)
        for wa, wb in itertools.product(("min", "max"), repeat=2):
            va, vb = bound(sa, wa), bound(sb, wb)
            if va is None or vb is None:
                continue
            body = copy.deepcopy(base)
            set_at(body, a.path, va)
            set_at(body, b.path, vb)
            cases.append((f"{a.pointer}={wa},{b.pointer}={wb}", body))
    return cases


def optional_filled(spec, path, base):
    """`base` with each absent optional object set to its example (one body per object)."""
    schema = spec["paths"][path]["post"]["requestBody"]["content"]["application/json"]["schema"]
    slots = []
    walk(spec, schema, base, [], slots)
    out = []
    for slot in slots:
        if slot.present or not slot.path:
            continue
        for alt in alternatives(spec, slot.schema):
            if "object" in types_of(alt) or "properties" in alt:
                ex = example_of(spec, alt)
                if isinstance(ex, dict) and ex:
                    body = copy.deepcopy(base)
                    try:
                        set_at(body, slot.path, ex)
                    except (KeyError, IndexError, TypeError):
                        continue
                    out.append((body, slot.path))
    return out


def made_valid(args, path, body, slot_path):
    """`body` if the server answers it, else `body` without the sibling of `slot_path` that
    conflicts with it (another viscosity law beside a filled `vogel`), or without all its
    siblings, else None."""
    if send(args.base, path, body, args.deadline_ms, args.timeout)[0] == 200:
        return body
    siblings = [k for k in get_at(body, slot_path[:-1]) if k != slot_path[-1]]
    for keys in [[k] for k in siblings] + [siblings]:
        trial = copy.deepcopy(body)
        for key in keys:
            del get_at(trial, slot_path[:-1])[key]
        if send(args.base, path, trial, args.deadline_ms, args.timeout)[0] == 200:
            return trial
    return None


def readme_bodies():
    """(path, body) for each README curl with a JSON body."""
    text = (ROOT / "README.md").read_text()
    out = []
    for m in re.finditer(r"curl[^\n]*?(/v1/[a-z0-9/-]+)(.*?)-d '(.*?)'", text, re.S):
        try:
            out.append((m.group(1), json.loads(m.group(3))))
        except json.JSONDecodeError:
            pass
    return out


def data_bodies():
    """(path, request) for each reference case in tests/data."""
    out = []
    for f in sorted((ROOT / "tests" / "data").rglob("*.json")):
        case = json.loads(f.read_text())
        if isinstance(case, dict) and "path" in case and isinstance(case.get("request"), dict):
            out.append((case["path"], case["request"]))
    return out


def non_finite(text):
    """True if the JSON text holds NaN or ±Infinity (or cannot be parsed)."""
    bad = []

    def const(name):
        bad.append(name)
        return 0.0

    try:
        json.loads(text, parse_constant=const)
    except ValueError:
        return False
    return bool(bad)


def send(base_url, path, body, deadline_ms, timeout):
    data = json.dumps(body, allow_nan=False).encode()
    req = urllib.request.Request(base_url + path, data=data, method="POST", headers={
        "content-type": "application/json", "x-stribeck-deadline-ms": str(deadline_ms)})
    t0 = time.monotonic()
    try:
        with urllib.request.urlopen(req, timeout=timeout) as r:
            status, text = r.status, r.read().decode()
    except urllib.error.HTTPError as e:
        status, text = e.code, e.read().decode()
    except Exception as e:  # connection refused, reset, timeout
        return None, f"{type(e).__name__}: {e}", time.monotonic() - t0
    return status, text, time.monotonic() - t0


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--base", default="http://127.0.0.1:18090")
    ap.add_argument("--spec", default=str(ROOT / "openapi" / "openapi.json"))
    ap.add_argument("--quick", action="store_true", help="examples only; no (min,max) pairs")
    ap.add_argument("--data", action="store_true",
                    help="also start from each reference case in tests/data (single fields)")
    ap.add_argument("--only", default="", help="paths containing this substring")
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--deadline-ms", type=int, default=20000)
    ap.add_argument("--timeout", type=float, default=30.0)
    ap.add_argument("--list", action="store_true", help="print the cases, send nothing")
    args = ap.parse_args()

    spec = json.loads(Path(args.spec).read_text())
    bases = []
    for path, item in sorted(spec["paths"].items()):
        op = item.get("post")
        if not op or args.only not in path:
            continue
        content = op["requestBody"]["content"]["application/json"]
        ex = content.get("example") or example_of(spec, content["schema"])
        bases.append((path, ex))
    known = {p for p, _ in bases}
    if not args.quick:
        bases += [(p, b) for p, b in readme_bodies() if p in known and (p, b) not in bases]
    # Further bases vary one field at a time (and equal pairs): their (min, max) pairs would
    # be ~10⁵ cases.
    extra = [(p, b) for p, b in data_bodies() if p in known and (p, b) not in bases] if args.data else []

    if not args.quick:
        # Each optional object the example leaves out (effects, dynamics, a custom fidelity …),
        # filled from its schema's example, so its own fields are varied too (single fields).
        for p, base in list(bases):
            for b, slot_path in optional_filled(spec, p, base):
                b = b if args.list else made_valid(args, p, b, slot_path)
                if b is not None and (p, b) not in bases and (p, b) not in extra:
                    extra.append((p, b))

    cases, seen = [], set()
    for path, base, quick in [(p, b, args.quick) for p, b in bases] + [(p, b, True) for p, b in extra]:
        for label, body in cases_for(spec, path, base, quick):
            key = (path, json.dumps(body, sort_keys=True))
            if key not in seen:
                seen.add(key)
                cases.append((path, label, body))
    if args.list:
        for path, label, body in cases:
            print(path, label)
        print(f"{len(cases)} cases", file=sys.stderr)
        return 0

    t0 = time.monotonic()
    failures, statuses = [], {}

    def run(case):
        path, label, body = case
        return case, send(args.base, path, body, args.deadline_ms, args.timeout)

    with concurrent.futures.ThreadPoolExecutor(max_workers=args.jobs) as pool:
        for (path, label, body), (status, text, dt) in pool.map(run, cases):
            statuses[status] = statuses.get(status, 0) + 1
            why = None
            if status is None:
                why = text
            elif status == 504:
                if dt > args.deadline_ms / 1000 + 2:
                    why = f"504 after {dt:.1f} s"
                else:
                    print(f"note: 504 within the deadline after {dt:.1f} s: {path} {label}",
                          file=sys.stderr, flush=True)
            elif status >= 500:
                why = f"{status}"
            elif non_finite(text):
                why = "non-finite number in response"
            if why:
                failures.append(path)
                print(json.dumps({"path": path, "case": label, "status": status, "why": why,
                                  "seconds": round(dt, 2), "response": (text or "")[:300],
                                  "body": body}), flush=True)
    dt = time.monotonic() - t0
    print(f"{len(cases)} cases, {len(failures)} failures, {dt:.0f} s, statuses "
          f"{dict(sorted(statuses.items(), key=lambda kv: str(kv[0])))}", file=sys.stderr)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
