#!/usr/bin/env python3
"""The include rule of include/phong/ (docs/design.md, 'Layers'): a header includes headers of
its own layer and the layers below it, never above. The layers, lowest first, are the folders
core < inputs < terms < routes < sum < ext, and the entry headers directly in include/phong/
(phong.hpp, batch.hpp, ...) above them all. Prints every violation; exit 1 if there is one."""
import os, re, sys
root = os.path.join(os.path.dirname(os.path.abspath(__file__)), '..', '..', 'include', 'phong')
LAYERS = ['core', 'inputs', 'terms', 'routes', 'sum', 'ext']
def layer_of(rel):
    top = rel.split('/')[0]
    if '/' not in rel: return len(LAYERS), 'entry'
    if top not in LAYERS: sys.exit(f'check_layers: {rel}: folder {top}/ is in no layer (add it to LAYERS)')
    return LAYERS.index(top), top
include = re.compile(r'^\s*#\s*include\s*[<"]([^>"]+)[>"]', re.M)
violations, edges = [], 0
for dirpath, _, files in os.walk(root):
    for f in files:
        if not f.endswith('.hpp'): continue
        path = os.path.join(dirpath, f)
        rel = os.path.relpath(path, root).replace(os.sep, '/')
        mine, my_name = layer_of(rel)
        for target in include.findall(open(path).read()):
            if target.startswith('phong/'): dest = os.path.normpath(os.path.join(root, target[len('phong/'):]))
            else: dest = os.path.normpath(os.path.join(dirpath, target))
            if not os.path.isfile(dest) or not dest.startswith(os.path.normpath(root) + os.sep): continue
            edges += 1
            theirs, their_name = layer_of(os.path.relpath(dest, root).replace(os.sep, '/'))
            if theirs > mine:
                violations.append(f'{rel} ({my_name}) includes {target} ({their_name}): a higher layer')
for v in sorted(violations): print(v)
print(f'check_layers: {edges} includes inside phong, {len(violations)} from a lower layer to a higher one')
sys.exit(1 if violations else 0)
