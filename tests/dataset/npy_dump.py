"""Prints a NumPy structured array as text, read by NumPy itself (an independent .npy reader).

    npy_dump.py FILE   ->  first line: name:dtype,... ; then one line per record, values as repr()
"""
import sys

import numpy as np

a = np.load(sys.argv[1])
print(",".join(f"{n}:{a.dtype[n].str}" for n in a.dtype.names))
for record in a:
    print(",".join(repr(v.item()) for v in record))
