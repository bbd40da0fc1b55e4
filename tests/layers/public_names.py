#!/usr/bin/env python3
"""Counts the public names a header reaches: every declaration named in namespace phong or one of
its sub-namespaces other than detail (presets::x counts as one name), from clang's AST of a
translation unit that includes the header. Usage: public_names.py HEADER [include-dir] [--list]"""
import json, os, subprocess, sys
header = sys.argv[1]; inc = sys.argv[2] if len(sys.argv) > 2 and not sys.argv[2].startswith('--') else os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'include')
src = f'#include <{header}>\n'
ast = subprocess.run(['clang++', '-std=c++20', '-I', inc, '-x', 'c++', '-fsyntax-only', '-Xclang', '-ast-dump=json', '-'],
                     input=src, capture_output=True, text=True, check=True).stdout
tu = json.loads(ast)
names = set()
KINDS = {'FunctionDecl', 'FunctionTemplateDecl', 'CXXRecordDecl', 'ClassTemplateDecl', 'VarDecl', 'VarTemplateDecl',
         'TypeAliasDecl', 'TypeAliasTemplateDecl', 'TypedefDecl', 'EnumDecl', 'ConceptDecl', 'UsingDecl',
         'ClassTemplateSpecializationDecl', 'ClassTemplatePartialSpecializationDecl', 'VarTemplateSpecializationDecl'}
SKIP_SPECIALIZATIONS = {'ClassTemplateSpecializationDecl', 'ClassTemplatePartialSpecializationDecl', 'VarTemplateSpecializationDecl'}
def walk(node, prefix):
    for d in node.get('inner', []):
        k = d.get('kind'); n = d.get('name')
        if k == 'NamespaceDecl':
            if n == 'detail' or n is None: continue
            walk(d, prefix + n + '::'); continue
        if k in KINDS and n and k not in SKIP_SPECIALIZATIONS and not d.get('isImplicit'):
            names.add(prefix + n)
for d in tu.get('inner', []):
    if d.get('kind') == 'NamespaceDecl' and d.get('name') == 'phong':
        walk(d, 'phong::')
if '--list' in sys.argv:
    for n in sorted(names): print(n)
print(f'{len(names)} public names reached by <{header}>')
