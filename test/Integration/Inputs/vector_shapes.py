"""Checks vector-shapes.test's dump of A after one base step from A[i] = i
against the values the scene's comment defines."""
import sys

import numpy as np

values = np.load(sys.argv[1])
expected = []
for i in range(len(values)):
    row = [i + k for k in range(4)]
    im, ir = i % 4, i % 3
    total = 4 * sum(row) + sum(row[:im]) + 2 * sum(row[:3]) + ir * sum(row[:im])
    expected.append(float(np.fmod(total, 1000)))
wrong = [i for i in range(len(values)) if values[i] != expected[i]]
print("items", len(values), "wrong", len(wrong),
      *(f"A[{i}]={values[i]} expected {expected[i]}" for i in wrong[:3]))
