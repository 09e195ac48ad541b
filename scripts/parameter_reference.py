#!/usr/bin/python3
"""The parameter reference of the manual, generated from the programs.

Reads what `mpm --print-parameters DIM json` (or mpm-fe's) prints for each
dimension, and writes one Markdown page: every subsection and entry, in
declaration order, with its default, the values it accepts and its
documentation. An entry whose default or pattern differs between dimensions
lists each; an entry declared in some dimensions only says which.

    parameter_reference.py --title T --out PAGE.md 1:mpm-1d.json 2:...
    parameter_reference.py --check 2:mpm-2d.json ...

With --check nothing is written: the program exits with status 1 and lists
every entry whose documentation is empty, so that the reference cannot have
an entry without a text.
"""
import argparse
import json
import re
import sys


def walk(tree, path, entries, order):
    """Collect entries by path, and every path (subsection or entry) once,
    in the order of the JSON (KeepDeclarationOrder keeps the declaration
    order)."""
    for key, node in tree.items():
        if not isinstance(node, dict):
            continue
        here = path + (key,)
        if here not in order:
            order.append(here)
        if "value" in node and "documentation" in node:
            entries[here] = node
        else:
            walk(node, here, entries, order)


def load(args):
    """dim -> {path: entry}, and the union of paths in first-seen order."""
    per_dim, order = {}, []
    for spec in args:
        dim, _, file = spec.partition(":")
        with open(file) as f:
            tree = json.load(f)
        entries = {}
        walk(tree, (), entries, order)
        per_dim[dim] = entries
    return per_dim, order


def check(per_dim):
    missing = sorted({" / ".join(p) for entries in per_dim.values()
                      for p, e in entries.items()
                      if not e.get("documentation", "").strip()})
    for m in missing:
        print(f"undocumented entry: {m}")
    if missing:
        print(f"{len(missing)} entries have no documentation")
        return 1
    n = len({p for entries in per_dim.values() for p in entries})
    print(f"all {n} entries documented")
    return 0


def code(text):
    """An inline code span that survives backticks and empty values."""
    if text == "":
        return "(empty)"
    fence = "``" if "`" in text else "`"
    pad = " " if text.startswith("`") or text.endswith("`") else ""
    return f"{fence}{pad}{text}{pad}{fence}"


def escape(text):
    """Documentation is plain text: keep Markdown from interpreting it.
    A documentation with several lines (a list, such as the benchmarks)
    becomes its first line and a bullet per further line."""
    text = re.sub(r"([\\*_<>\[\]|#`$])", r"\\\1", text)
    lines = [l.strip() for l in text.split("\n") if l.strip()]
    if len(lines) <= 1:
        return " ".join(lines)
    return lines[0] + "\n\n" + "\n".join("- " + l for l in lines[1:])


def per_dimension(values, dims, fmt):
    """One value when all dimensions agree, else one per dimension."""
    distinct = {values[d] for d in values}
    if len(distinct) == 1:
        return fmt(next(iter(distinct)))
    return "; ".join(f"{d}D: {fmt(values[d])}" for d in dims if d in values)


def write(per_dim, order, title, intro, out):
    dims = sorted(per_dim)
    lines = [f"# {title}", ""] + ([intro, ""] if intro else [])
    for path in order:
        present = [d for d in dims if path in per_dim[d]]
        if not present:
            # a subsection: a heading, level 2 at the top and level 3 below
            # (the full path names it, so deeper levels need no level 4)
            level = "##" if len(path) == 1 else "###"
            lines += [f"{level} {' / '.join(path)}", ""]
            continue
        entry = {d: per_dim[d][path] for d in present}
        name = path[-1]
        lines.append(f"**{code(name)}**" +
                     ("" if len(present) == len(dims) else
                      " (" + ", ".join(f"{d}D" for d in present) + " only)"))
        lines.append("")
        default = per_dimension({d: e["default_value"]
                                 for d, e in entry.items()}, dims, code)
        accepts = per_dimension({d: e.get("pattern_description", "")
                                 for d, e in entry.items()}, dims,
                                lambda s: code(s) if s else "any text")
        doc = per_dimension({d: e["documentation"]
                             for d, e in entry.items()}, dims, escape)
        lines.append(f"- default: {default}")
        lines.append(f"- accepts: {accepts}")
        lines.append("")
        lines.append(doc if doc else "(no documentation)")
        lines.append("")
    with open(out, "w") as f:
        f.write("\n".join(lines))


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--title", default="Parameters")
    ap.add_argument("--intro", default="")
    ap.add_argument("--out")
    ap.add_argument("json", nargs="+", help="DIM:FILE.json")
    a = ap.parse_args()
    per_dim, order = load(a.json)
    if a.check:
        return check(per_dim)
    write(per_dim, order, a.title, a.intro, a.out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
