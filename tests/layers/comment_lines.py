#!/usr/bin/env python3
"""Counts the lines of C++ files and, of those, the comment lines: lines with comment text and no
code (a table row `/* label */ {1, 2},` is code; string literals are not searched for comment
markers). Usage: comment_lines.py FILE... -> prints "<lines> <comment lines>"."""
import sys

def count(text):
    lines = comments = 0
    in_block = False
    for line in text.split('\n')[:-1] if text.endswith('\n') else text.split('\n'):
        lines += 1
        code = has_comment = False
        i, n = 0, len(line)
        in_str = None
        while i < n:
            c = line[i]
            if in_block:
                has_comment = True
                if line.startswith('*/', i): in_block = False; i += 2; continue
                i += 1; continue
            if in_str:
                if c == '\\': i += 2; continue
                if c == in_str: in_str = None
                i += 1; continue
            if line.startswith('//', i): has_comment = True; break
            if line.startswith('/*', i): in_block = True; has_comment = True; i += 2; continue
            if c in '"\'': in_str = c; code = True; i += 1; continue
            if not c.isspace(): code = True
            i += 1
        if has_comment and not code: comments += 1
    return lines, comments

total_lines = total_comments = 0
for path in sys.argv[1:]:
    l, c = count(open(path, encoding='utf-8').read())
    total_lines += l; total_comments += c
print(total_lines, total_comments)
