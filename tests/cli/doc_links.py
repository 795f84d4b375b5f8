#!/usr/bin/env python3
"""Every relative link of README.md and docs/*.md resolves.

A link is a Markdown link or image, [text](target) or ![alt](target),
outside code (fenced blocks and `code spans`). Links with a scheme
(https:, mailto:, ...) are not checked. A relative target must name an
existing file or folder, relative to the doc that holds the link; where it
has a #anchor and names a Markdown file (or is only #anchor: the doc
itself), the anchor must be one of that file's headings, spelled as GitHub
spells them: the heading's text (inline code, emphasis and links reduced to
their text) in lower case, every character that is not a letter, a digit,
a space, '-' or '_' dropped, each space turned into '-'; a heading that
repeats an earlier one gets -1, -2, ... appended.

Usage: doc_links.py [SOURCE_DIR]   (default: the repository of this script)
Exit status 0 when every link resolves, 1 listing each broken link as
FILE:LINE: [text](target): why
"""
import glob
import os
import re
import sys

LINK = re.compile(r"!?\[((?:[^\[\]]|\[[^\[\]]*\])*)\]\(\s*<?([^()\s>]*(?:\([^()\s]*\)[^()\s>]*)*)>?"
                  r"(?:\s+\"[^\"]*\")?\s*\)")
SCHEME = re.compile(r"^[A-Za-z][A-Za-z0-9+.-]*:")
HEADING = re.compile(r"^ {0,3}(#{1,6})\s+(.*?)\s*#*\s*$")


def prose_lines(text):
    """(line number, line) outside fenced code blocks."""
    fence = None
    for number, line in enumerate(text.split("\n"), 1):
        m = re.match(r"^ {0,3}(`{3,}|~{3,})", line)
        if m:
            if fence is None:
                fence = m.group(1)[0] * len(m.group(1))
            elif m.group(1).startswith(fence):
                fence = None
            continue
        if fence is None:
            yield number, line


def without_code_spans(line):
    """The line with its `code spans` blanked (their length kept)."""
    return re.sub(r"(`+)(.+?)\1", lambda m: " " * len(m.group(0)), line)


def slug(heading):
    """GitHub's anchor of a heading's text."""
    text = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # links, images: their text
    text = re.sub(r"<[^>]+>", "", text)                        # inline HTML tags
    text = text.replace("`", "")
    text = text.strip().lower()
    text = re.sub(r"[^\w\- ]", "", text)                        # punctuation dropped
    return text.replace(" ", "-")


_anchors = {}


def anchors(path):
    """The anchors of the headings of the Markdown file PATH."""
    if path not in _anchors:
        seen, found = {}, set()
        with open(path, encoding="utf-8") as f:
            for _, line in prose_lines(f.read()):
                m = HEADING.match(line)
                if not m:
                    continue
                base = slug(m.group(2))
                n = seen.get(base, 0)
                found.add(base if n == 0 else "%s-%d" % (base, n))
                seen[base] = n + 1
        _anchors[path] = found
    return _anchors[path]


def check(doc, root):
    """[broken link lines] of the doc DOC."""
    broken = []
    rel = os.path.relpath(doc, root)
    with open(doc, encoding="utf-8") as f:
        text = f.read()
    for number, line in prose_lines(text):
        for m in LINK.finditer(without_code_spans(line)):
            # the code spans blanked keep their length: the label as written
            label, target = line[m.start(1):m.end(1)], m.group(2)
            if not target or SCHEME.match(target):
                continue
            path, _, anchor = target.partition("#")
            where = "%s:%d: [%s](%s): " % (rel, number, label, target)
            if path:
                resolved = os.path.normpath(os.path.join(os.path.dirname(doc), path))
                if not os.path.exists(resolved):
                    broken.append(where + "no file %s" % os.path.relpath(resolved, root))
                    continue
            else:
                resolved = doc
            if anchor and resolved.endswith(".md") and os.path.isfile(resolved):
                if anchor not in anchors(resolved):
                    broken.append(where + "no heading with the anchor #%s in %s"
                                  % (anchor, os.path.relpath(resolved, root)))
    return broken


def main(argv):
    root = os.path.abspath(argv[1] if len(argv) > 1 else
                           os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))
    docs = [os.path.join(root, "README.md")] + sorted(glob.glob(os.path.join(root, "docs", "*.md")))
    docs = [d for d in docs if os.path.isfile(d)]
    if not docs:
        print("doc_links: no README.md or docs/*.md under %s" % root)
        return 1
    broken = []
    links = 0
    for doc in docs:
        with open(doc, encoding="utf-8") as f:
            links += sum(len(LINK.findall(without_code_spans(l))) for _, l in prose_lines(f.read()))
        broken += check(doc, root)
    for b in broken:
        print(b)
    if broken:
        print("doc_links: %d of %d links in %d docs are broken" % (len(broken), links, len(docs)))
        return 1
    print("doc_links: all %d links in %d docs resolve" % (links, len(docs)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
