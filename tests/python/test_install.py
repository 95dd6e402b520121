"""tools/install-python.sh puts a package that works from any folder into a venv made with
--system-site-packages, and refuses a venv that cannot see Debian's packages."""

import os
import subprocess
import unittest

from python_test_support import BUILD_DIR, SOURCE_DIR, TempDirTest, example

SCRIPT = os.path.join(SOURCE_DIR, "tools", "install-python.sh")


class InstallTest(TempDirTest):

    def make_venv(self, name, *flags):
        venv = os.path.join(self.dir, name)
        subprocess.run(["/usr/bin/python3", "-m", "venv", "--without-pip", *flags, venv],
                       check=True)
        return os.path.join(venv, "bin", "python")

    def install(self, python):
        return subprocess.run(["bash", SCRIPT, "--no-build", "--build-dir", BUILD_DIR,
                               "--python", python], capture_output=True, text=True)

    def test_installs_into_a_venv_with_system_site_packages(self):
        python = self.make_venv("venv", "--system-site-packages")
        result = self.install(python)
        self.assertEqual(result.returncode, 0, result.stderr)
        environment = {k: v for k, v in os.environ.items() if k != "PYTHONPATH"}
        check = subprocess.run(
            [python, "-c", "import areagraph, sys; g = areagraph.segment(sys.argv[1]); "
             "print(areagraph.__file__, len(g.areas), g.to_networkx())",
             example("office_small.png")],
            cwd="/", env=environment, capture_output=True, text=True)
        self.assertEqual(check.returncode, 0, check.stderr)
        self.assertTrue(check.stdout.startswith(os.path.join(self.dir, "venv")), check.stdout)
        self.assertIn("MultiGraph", check.stdout)

    def test_refuses_a_venv_without_debians_packages(self):
        result = self.install(self.make_venv("bare"))
        self.assertEqual(result.returncode, 1)
        self.assertIn("a venv needs --system-site-packages", result.stderr)
        self.assertEqual(len(result.stderr.strip().splitlines()), 1, result.stderr)


if __name__ == "__main__":
    unittest.main()
