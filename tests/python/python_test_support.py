"""What the Python package's tests share: where the build and the checkout are, running the
command-line tools, and the maps."""

import json
import os
import shutil
import subprocess
import tempfile
import unittest

SOURCE_DIR = os.environ["AG_SOURCE_DIR"]
BUILD_DIR = os.environ["AG_BUILD_DIR"]
BIN_DIR = os.environ["AG_TEST_BIN_DIR"]
SHARED_DATA = os.path.join(os.path.dirname(SOURCE_DIR), "shared", "data")


def example(name):
    """A map of examples/."""
    return os.path.join(SOURCE_DIR, "examples", name)


def shared_map(relative):
    """A map of ../shared/data, or a skip when the data is not there."""
    path = os.path.join(SHARED_DATA, relative)
    if not os.path.exists(path):
        raise unittest.SkipTest("no " + path)
    return path


def run_tool(tool, *args, check=True):
    """Runs build/bin/<tool>; returns the CompletedProcess (text output)."""
    result = subprocess.run([os.path.join(BIN_DIR, tool), *args], capture_output=True, text=True)
    if check and result.returncode != 0:
        raise AssertionError("%s failed (%d): %s" % (tool, result.returncode, result.stderr))
    return result


def tool_error(tool, *args):
    """The message a tool prints for a failure, without its "<tool>: " prefix."""
    result = run_tool(tool, *args, check=False)
    assert result.returncode != 0, result.stdout
    line = result.stderr.strip()
    assert "\n" not in line, line
    assert line.startswith(tool + ": "), line
    return line[len(tool) + 2:]


def exported_json(store, map_name):
    """ag-export --format json of the map, parsed."""
    return json.loads(run_tool("ag-export", "--store", store, "--map", map_name, "--format",
                               "json", "--out", "-").stdout)


class TempDirTest(unittest.TestCase):
    """A test with a fresh temporary folder in self.dir."""

    def setUp(self):
        self.dir = tempfile.mkdtemp(prefix="areagraph-python-")
        self.addCleanup(shutil.rmtree, self.dir, True)
