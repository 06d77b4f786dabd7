#!/usr/bin/env python3
"""Checks a report folder: every href and src in every .html file names a file that exists inside
the folder (relative paths only, so the folder can be moved), and every #anchor exists on its page.

usage: report_check_links.py REPORT_DIR     exit 0 and "links ok: N" when all resolve, else 1"""
import sys
from html.parser import HTMLParser
from pathlib import Path
from urllib.parse import unquote, urlsplit


class Links(HTMLParser):
    def __init__(self):
        super().__init__()
        self.links, self.ids = [], set()

    def handle_starttag(self, tag, attrs):
        for k, v in attrs:
            if k in ("href", "src") and v is not None:
                self.links.append(v)
            if k == "id" and v:
                self.ids.add(v)


def parse(page):
    p = Links()
    p.feed(page.read_text())
    return p


def broken_links(folder):
    folder = Path(folder).resolve()
    pages = {page: parse(page) for page in sorted(folder.glob("**/*.html"))}
    bad, n = [], 0
    for page, p in pages.items():
        for link in p.links:
            n += 1
            u = urlsplit(link)
            if u.scheme or u.netloc:
                bad.append(f"{page.name}: {link} (not a relative path: the folder could not be moved)")
                continue
            target = (page.parent / unquote(u.path)).resolve() if u.path else page
            if folder not in target.parents and target != folder:
                bad.append(f"{page.name}: {link} (outside the report folder)")
            elif not target.is_file():
                bad.append(f"{page.name}: {link} (no such file)")
            elif u.fragment and target.suffix == ".html":
                ids = pages[target].ids if target in pages else parse(target).ids
                if unquote(u.fragment) not in ids:
                    bad.append(f"{page.name}: {link} (no id '{u.fragment}' on {target.name})")
    return bad, n, len(pages)


def main():
    if len(sys.argv) != 2 or not Path(sys.argv[1]).is_dir():
        sys.exit("usage: report_check_links.py REPORT_DIR")
    bad, n, pages = broken_links(sys.argv[1])
    for b in bad:
        print(f"broken: {b}")
    if bad or not pages:
        print(f"links FAIL: {len(bad)} of {n} links broken in {pages} pages")
        sys.exit(1)
    print(f"links ok: {n} links in {pages} pages resolve")


if __name__ == "__main__":
    main()
