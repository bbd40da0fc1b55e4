#!/usr/bin/env python3
"""Functions in include/phong longer than N lines (default 80), from clang's AST of a translation
unit including every entry header. Usage: long_functions.py [N]"""
import json, subprocess, sys, os
N = int(sys.argv[1]) if len(sys.argv) > 1 else 80
root = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..')
entries = [h for h in ('phong.hpp', 'batch.hpp', 'primitives.hpp', 'bsdf.hpp', 'accuracy.hpp') if os.path.exists(os.path.join(root, 'include/phong', h))]
src = ''.join(f'#include <phong/{h}>\n' for h in entries)
ast = subprocess.run(['clang++', '-std=c++20', '-I', os.path.join(root, 'include'), '-x', 'c++', '-fsyntax-only', '-Xclang', '-ast-dump=json', '-'],
                     input=src, capture_output=True, text=True, check=True).stdout
tu = json.loads(ast)
found = {}
cur = [None]
def upd(d):
    if not isinstance(d, dict): return None
    line = None
    for sub in (d.get('spellingLoc'), d.get('expansionLoc'), d):
        if isinstance(sub, dict):
            if 'file' in sub: cur[0] = sub['file']
    for sub in (d.get('expansionLoc'), d):
        if isinstance(sub, dict) and 'line' in sub: line = sub['line']
    return line
def walk(node):
    upd(node.get('loc', {}))
    rng = node.get('range', {})
    bl = upd(rng.get('begin', {})); bfile = cur[0]
    el = upd(rng.get('end', {}))
    if node.get('kind') in ('FunctionDecl', 'CXXMethodDecl') and any(c.get('kind') == 'CompoundStmt' for c in node.get('inner', [])):
        if bfile and 'include/phong/' in bfile and bl and el and el - bl + 1 > N:
            key = (os.path.normpath(bfile).split('include/', 1)[-1], node.get('name', '?'), bl)
            found[key] = el - bl + 1
    for c in node.get('inner', []): walk(c)
walk(tu)
for (f, n, l), length in sorted(found.items(), key=lambda kv: -kv[1]): print(f'{length:4d} lines  {f}:{l}  {n}')
print(f'{len(found)} functions over {N} lines')
