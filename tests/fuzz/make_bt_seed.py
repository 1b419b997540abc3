#!/usr/bin/env python3
import sys
# Writes a small OctoMap .bt tree to stdout: two 1.6 m x 1.2 m walls of
# 0.1 m voxels and a free one in front of them (384 occupied, 192 free
# leaves, 475 bytes): the bt fuzzer's seed regressions/bt/seed-small-walls.bt
# (python3 tests/fuzz/make_bt_seed.py > tests/fuzz/regressions/bt/seed-small-walls.bt).
DEPTH = 16
def child_index(key, depth):
    b = DEPTH - 1 - depth
    return ((key[0] >> b) & 1) | (((key[1] >> b) & 1) << 1) | (((key[2] >> b) & 1) << 2)
def insert(tree, key, value, depth=0):
    i = child_index(key, depth)
    if depth == DEPTH - 1:
        tree[i] = value
        return
    insert(tree.setdefault(i, {}), key, value, depth + 1)
def write(tree, out):
    codes = 0
    for i in range(8):
        if i not in tree: continue
        c = tree[i]
        code = 3 if isinstance(c, dict) else (2 if c else 1)  # inner, occupied, free
        codes |= code << (2 * i)
    out.append(codes & 0xFF); out.append((codes >> 8) & 0xFF)
    for i in range(8):
        if isinstance(tree.get(i), dict): write(tree[i], out)
root = {}; n = 0
for u in range(16):
    for v in range(12):
        insert(root, (32768 + 20, 32768 + u, 32768 + v), True)
        insert(root, (32768 + u, 32768 + 20, 32768 + v), True)
        insert(root, (32768 + 10, 32768 + u, 32768 + v), False)
data = []
write(root, data)
def count(t): return 1 + sum(count(c) if isinstance(c, dict) else 1 for c in t.values())
header = "# Octomap OcTree binary file\nid OcTree\nsize %d\nres 0.1\ndata\n" % count(root)
sys.stdout.buffer.write(header.encode() + bytes(data))
