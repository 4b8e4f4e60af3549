"""The tables of docs/ that come from a run: each sits between `<!-- KIND:NAME -->` and
`<!-- /KIND:NAME -->` and is rewritten whole, opening with the name of the run that made it.
Shared by scripts/bench_report.py (KIND bench) and scripts/accuracy_report.py (KIND accuracy)."""
import os
import re
import sys


def markdown_files(places):
    """The .md files among `places` (a path or a list of paths): a folder's, sorted, or a file."""
    for place in [places] if isinstance(places, str) else places:
        if os.path.isdir(place):
            yield from (os.path.join(place, f) for f in sorted(os.listdir(place)) if f.endswith(".md"))
        else:
            yield place


def rewrite(docs, kind, tables, run_name):
    """Rewrites every `kind` table of the .md files in `docs` (a folder, a file, or a list of
    them). `tables` maps a name to a function that returns the table's lines, or None when the
    run lacks its figures (the table is then left as it was). An unknown name or a missing end
    marker stops the script."""
    for path in markdown_files(docs):
        text = open(path).read()
        changed = text
        for name in re.findall(rf"<!-- {kind}:([a-z0-9-]+) -->", text):
            if name not in tables:
                sys.exit(f"{kind}: {path}: no table named {name!r} (known: {', '.join(sorted(tables))})")
            lines = tables[name]()
            if lines is None:
                print(f"{kind}: {path}: table {name} left as it was (the run lacks its figures)")
                continue
            block = "\n".join([f"<!-- {kind}:{name} -->", f"{run_name}:", ""] + lines + [f"<!-- /{kind}:{name} -->"])
            pattern = re.compile(rf"<!-- {kind}:{name} -->.*?<!-- /{kind}:{name} -->", re.S)
            if not pattern.search(changed):
                sys.exit(f"{kind}: {path}: table {name} has no end marker <!-- /{kind}:{name} -->")
            changed = pattern.sub(lambda _: block, changed)
            print(f"{kind}: {path}: table {name} written")
        if changed != text:
            tmp = path + ".tmp"
            with open(tmp, "w") as f:
                f.write(changed)
            os.replace(tmp, path)
