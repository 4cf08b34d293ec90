"""What the command-line checks share (verif/cli/check_*.py, verif/hls_export/check_export_safety.py):
a failure line and exit status 1, a command run with its output captured, and what a folder holds
(to show that a refused run changed nothing)."""
import hashlib
import os
import subprocess
import sys


def fail(msg):
    print("FAIL: " + msg)
    sys.exit(1)


def run(cmd, **kw):
    """cmd run to its end, stdout and stderr captured as text."""
    return subprocess.run(cmd, capture_output=True, text=True, **kw)


def snapshot(root):
    """Every file and folder under root: relative path -> digest of its bytes (None: a folder)."""
    found = {}
    for folder, dirs, files in os.walk(root):
        for d in dirs:
            found[os.path.relpath(os.path.join(folder, d), root)] = None
        for f in files:
            path = os.path.join(folder, f)
            with open(path, "rb") as fh:
                found[os.path.relpath(path, root)] = hashlib.sha256(fh.read()).hexdigest()
    return found
