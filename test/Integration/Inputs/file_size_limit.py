"""file_size_limit.py BYTES COMMAND...: runs COMMAND with every file it
writes limited to BYTES (RLIMIT_FSIZE) and SIGXFSZ ignored, so that a write
past the limit fails with EFBIG ("File too large"), as on a full disk,
instead of killing it (checkpoint-write-fails.test).

Both are inherited through exec: the command is this process, and its exit
status is this one's.
"""
import os
import resource
import signal
import sys

limit = int(sys.argv[1])
signal.signal(signal.SIGXFSZ, signal.SIG_IGN)
resource.setrlimit(resource.RLIMIT_FSIZE, (limit, limit))
os.execvp(sys.argv[2], sys.argv[2:])
