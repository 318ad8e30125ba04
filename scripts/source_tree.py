"""The files of a source tree, for the checks that read it (check_layers.py, check_protocol_names.py).

Build folders and hidden folders at the top are not entered: the tests run while these checks do
(ctest -j), and they create and remove folders under build/ (DVPR_TEST_TMP), which a walk that
entered them could find gone between listing and reading a folder.
"""
import os
import pathlib


def tree_files(root):
    """Every file under `root`, sorted, except under its top-level build* and hidden folders."""
    found = []
    for folder, subfolders, names in os.walk(root):
        if pathlib.Path(folder) == pathlib.Path(root):
            subfolders[:] = [d for d in subfolders if not d.startswith("build") and not d.startswith(".")]
        found.extend(pathlib.Path(folder) / name for name in names)
    return sorted(found)
