#!/usr/bin/python3
"""The rules of docs/ARCHITECTURE.md that a script can check, run as tests (tests/CMakeLists.txt):

    scripts/house_rules.py mirror           every libacd/src/ROOM/X.cpp has tests/ROOM/test_X.cpp
    scripts/house_rules.py public-headers   no installed header includes CGAL (or Boost), and
                                            no installed header is a forwarding stub
    scripts/house_rules.py api-example      docs/API.md shows tests/packaging/consumer/main.cpp as it is
    scripts/house_rules.py all

(File and function sizes: scripts/code_size.py.) Prints what breaks a rule, one line each,
and exits 1 when anything does."""
import pathlib
import re
import sys

ROOT = pathlib.Path(__file__).resolve().parent.parent


def mirror():
    src = ROOT / "libacd" / "src"
    broken = []
    for cpp in sorted(src.rglob("*.cpp")):
        rel = cpp.relative_to(src)
        test = ROOT / "tests" / rel.parent / ("test_" + rel.name)
        if not test.exists():
            broken.append("libacd/src/%s has no test: tests/%s" % (rel, test.relative_to(ROOT / "tests")))
    return broken


INCLUDE = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)


def public_headers():
    broken = []
    inc = ROOT / "libacd" / "include"
    for h in sorted(inc.rglob("*.hpp*")):
        text = h.read_text(errors="replace")
        rel = h.relative_to(inc)
        for name in INCLUDE.findall(text):
            if name.startswith(("CGAL/", "boost/")):
                broken.append("%s includes <%s>: CGAL and Boost stay in libacd's sources" % (rel, name))
        code = [l for l in text.splitlines() if l.strip() and not l.strip().startswith("//")]
        if len(code) <= 2 and all(l.startswith(("#pragma", "#include")) for l in code) and any(
                l.startswith("#include") for l in code):
            broken.append("%s only forwards to another header: include that one" % rel)
    return broken


def api_example():
    doc = (ROOT / "docs" / "API.md").read_text()
    example = (ROOT / "tests" / "packaging" / "consumer" / "main.cpp").read_text()
    blocks = re.findall(r"```cpp\n(.*?)```", doc, re.S)
    if example not in blocks:
        return ["docs/API.md does not show tests/packaging/consumer/main.cpp as it is (a ```cpp block)"]
    return []


def main():
    what = sys.argv[1] if len(sys.argv) > 1 else "all"
    checks = {"mirror": mirror, "public-headers": public_headers, "api-example": api_example}
    if what != "all" and what not in checks:
        sys.exit(__doc__)
    broken = []
    for name, check in checks.items():
        if what in ("all", name):
            broken += check()
    for line in broken:
        print(line)
    sys.exit(1 if broken else 0)


if __name__ == "__main__":
    main()
