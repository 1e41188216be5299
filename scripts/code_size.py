#!/usr/bin/python3
"""The longest files and functions of C++ sources, against the limits of docs/ARCHITECTURE.md
(800 lines a file, 120 a function); exits 1 when one is over.

    scripts/code_size.py libacd [--top 10] [--max-file 800] [--max-function 120]

Functions are found by brace matching: a block opened outside any function whose header
contains '(' and is not a control statement, class, namespace or initialiser list.
Lambdas and local classes count towards the function around them."""
import argparse, pathlib, re, sys

def strip(text):
    # blank out comments and string/char literals, keeping line structure
    out, i, n = [], 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith('//', i):
            j = text.find('\n', i); j = n if j < 0 else j
            out.append(' ' * (j - i)); i = j
        elif text.startswith('/*', i):
            j = text.find('*/', i + 2); j = n if j < 0 else j + 2
            out.append(''.join(ch if ch == '\n' else ' ' for ch in text[i:j])); i = j
        elif text.startswith('R"', i):
            m = re.match(r'R"([^(]*)\(', text[i:])
            end = text.find(')' + m.group(1) + '"', i) if m else -1
            j = n if end < 0 else end + len(m.group(1)) + 2
            out.append(''.join(ch if ch == '\n' else ' ' for ch in text[i:j])); i = j
        elif c in '"\'':
            j = i + 1
            while j < n and text[j] != c:
                j += 2 if text[j] == '\\' else 1
            out.append(' ' * (j + 1 - i)); i = j + 1
        else:
            out.append(c); i += 1
    return ''.join(out)

def functions(path):
    text = strip(path.read_text(errors='replace'))
    stack = []  # kinds of open blocks: 'scope' (namespace/class/extern) or 'func' or 'other'
    header_start = 0
    result = []
    for i, c in enumerate(text):
        if c == '{':
            in_func = any(k[0] == 'func' for k in stack)
            kind = 'other'
            if not in_func:
                header = text[header_start:i]
                h = ' '.join(header.split())
                if re.search(r'\b(namespace|class|struct|union|enum)\b[^()]*$', h) or h.endswith('extern "C"') or re.search(r'=\s*$', h) or not h:
                    kind = 'scope'
                elif '(' in h and not re.match(r'^(if|for|while|switch|catch|else|do)\b', h):
                    kind = 'func'
                else:
                    kind = 'scope'
            stack.append((kind, i, text.count('\n', 0, i) + 1, text[header_start:i]))
            header_start = i + 1
        elif c == '}':
            if stack:
                kind, start, line, header = stack.pop()
                if kind == 'func' and not any(k[0] == 'func' for k in stack):
                    end = text.count('\n', 0, i) + 1
                    name = re.findall(r'([~\w:]+|operator\s*\S+)\s*\(', ' '.join(header.split()))
                    first_line = line
                    result.append((end - first_line + 1, name[0] if name else '?', line))
            header_start = i + 1
        elif c == ';':
            if not any(k[0] == 'func' for k in stack):
                header_start = i + 1
    return result

def main():
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument('paths', nargs='+')
    ap.add_argument('--max-file', type=int, default=800)
    ap.add_argument('--max-function', type=int, default=120)
    ap.add_argument('--top', type=int, default=10)
    a = ap.parse_args()
    files = []
    for p in a.paths:
        p = pathlib.Path(p)
        files += sorted(p.rglob('*.[ch]pp')) if p.is_dir() else [p]
    sizes = sorted(((len(f.read_text(errors='replace').splitlines()), f) for f in files), reverse=True)
    funcs = sorted(((n, f'{f}:{line} {name}') for f in files for n, name, line in functions(f)), reverse=True)
    print(f'longest files (limit {a.max_file}):')
    for n, f in sizes[:a.top]: print(f'  {n:5d}  {f}')
    print(f'longest functions (limit {a.max_function}):')
    for n, f in funcs[:a.top]: print(f'  {n:5d}  {f}')
    over = [f for n, f in sizes if n > a.max_file] + [f for n, f in funcs if n > a.max_function]
    print(f'{len(over)} over the limits')
    return 1 if over else 0

sys.exit(main())
