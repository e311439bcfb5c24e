"""same_state.py OUTPUT.npz BUFFER DUMP.npy: the last output of BUFFER in
OUTPUT.npz (a Python run) equals sim-run's dump DUMP.npy bit for bit."""
import sys

import numpy as np

with np.load(sys.argv[1]) as data:
    ours = data["buffer/" + sys.argv[2]][-1]
theirs = np.load(sys.argv[3])
same = (ours.dtype == theirs.dtype and ours.shape == theirs.shape and
        ours.tobytes() == theirs.tobytes())
print(f"{sys.argv[2]}: {'equal' if same else 'DIFFERENT'} {ours.dtype} "
      f"{ours.shape}")
sys.exit(0 if same else 1)
