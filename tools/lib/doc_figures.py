"""Measured figures in docs/ are written by the tool that measures them.

A block of figures in a page of docs/ sits between two markers that name the
tool and the block:

    <!-- figures: tools/quadrature_study (newtonian) -->
    ...table, written by the tool...
    <!-- end figures -->

write_block(page, tool, name, text) replaces what is between them (the
markers stay) and adds the machine and the date, so a rerun of the tool
updates the page and nobody types a figure.

As a command (for tools written in bash): doc_figures.py PAGE TOOL NAME < TEXT
"""
import datetime
import os
import platform
import re
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))


def machine():
    cores = os.cpu_count() or 0
    model = ""
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.startswith("model name"):
                    model = line.split(":", 1)[1].strip()
                    break
    except OSError:
        pass
    return f"{platform.node() or 'this machine'}, {cores} cores{', ' + model if model else ''}"


def table(header, lines):
    """A Markdown table: `header` the column names, `lines` the rows' cells (text)."""
    return "\n".join(["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
                     + ["| " + " | ".join(line) + " |" for line in lines])


def block_in(page, tool, name):
    """docs/`page`'s path and text, block `name` of `tool`'s opening marker,
    and a pattern whose group 1 is what the block holds."""
    path = os.path.join(ROOT, "docs", page)
    with open(path, encoding="utf-8") as f:
        doc = f.read()
    begin = f"<!-- figures: {tool} ({name}) -->"
    return path, doc, begin, re.compile(re.escape(begin) + r"\n(.*?)<!-- end figures -->", re.S)


def write_block(page, tool, name, text):
    """Puts `text` (Markdown) in block `name` of `tool` in docs/`page`."""
    path, doc, begin, pattern = block_in(page, tool, name)
    if not pattern.search(doc):
        sys.exit(f"{path}: no block '{begin}' ... '<!-- end figures -->' to write")
    stamp = f"_Written by `{tool}` on {datetime.date.today().isoformat()}, {machine()}._"
    block = f"{begin}\n{text.rstrip()}\n\n{stamp}\n<!-- end figures -->"
    doc = pattern.sub(lambda _: block, doc, count=1)
    tmp = path + ".tmp"
    with open(tmp, "w", encoding="utf-8") as f:
        f.write(doc)
    os.replace(tmp, path)
    print(f"wrote block '{name}' of {os.path.relpath(path, ROOT)}")


def block_rows(page, tool, name):
    """The table rows of block `name` of `tool` in docs/`page` as lists of
    cells, and the date its stamp gives ('' when none): what a tool that
    rewrites some of its rows keeps of the others."""
    _, doc, _, pattern = block_in(page, tool, name)
    found = pattern.search(doc)
    if not found:
        return [], ""
    lines = [line for line in found.group(1).splitlines() if line.startswith("| ")]
    rows = [[cell.strip() for cell in line.strip().strip("|").split(" | ")] for line in lines[1:]]
    date = re.search(r"on (\d{4}-\d{2}-\d{2}),", found.group(1))
    return rows, date.group(1) if date else ""


if __name__ == "__main__":
    if len(sys.argv) != 4:
        sys.exit("usage: doc_figures.py PAGE TOOL NAME < TEXT")
    write_block(sys.argv[1], sys.argv[2], sys.argv[3], sys.stdin.read())
