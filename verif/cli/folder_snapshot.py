"""What a folder holds, to show that a refused run changed nothing (issue 28's "nothing written"
tests: verif/cli/check_output_collisions.py, check_tool_folders.py,
verif/hls_export/check_export_safety.py)."""
import hashlib
import os


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
