"""The report under hostile files (docs/trust.md): links planted where it writes are
replaced, never written through; a PLY header's vertex count, a column of
non-finite times, a garbage file and a zones folder outside zones/ each end in
exit 2 and a message naming the file, within a bounded address space.
Run: /usr/bin/python3 -m unittest discover -s tests/report"""
import os
import resource
import subprocess
import sys
import tempfile
import types
import unittest

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")
sys.path.insert(0, os.path.join(ROOT, "report"))
from proxsim_report.run_data import RunError  # noqa: E402
from proxsim_report.safe_files import UnsafeFileError, write_bytes  # noqa: E402

# the address space of a report run: the 1e8 vertices a header declares once took 2.4 GB
REPORT_ADDRESS_SPACE_BYTES = 1536 << 20


def _bounded():
    resource.setrlimit(resource.RLIMIT_AS, (REPORT_ADDRESS_SPACE_BYTES, REPORT_ADDRESS_SPACE_BYTES))


class HostileRunTest(unittest.TestCase):
    def setUp(self):
        self._dir = tempfile.TemporaryDirectory()
        self.root = self._dir.name
        self.out = os.path.join(self.root, "run")
        r = subprocess.run([sys.executable, "tests/data/report_sample/make_sample.py", self.out, "--no-robot"],
                           capture_output=True, text=True, cwd=ROOT)
        self.assertEqual(r.returncode, 0, r.stderr)
        self.victim = os.path.join(self.root, "victim.txt")
        with open(self.victim, "w") as f:
            f.write("mine\n")

    def tearDown(self):
        self._dir.cleanup()

    def make_report(self):
        return subprocess.run([sys.executable, "report/make_report.py", self.out], capture_output=True, text=True,
                              cwd=ROOT, preexec_fn=_bounded, timeout=300)

    def assert_victim_untouched(self):
        with open(self.victim) as f:
            self.assertEqual(f.read(), "mine\n")

    def test_a_link_planted_in_report_is_replaced_not_written_through(self):
        os.makedirs(os.path.join(self.out, "report"))
        planted = os.path.join(self.out, "report", "paper_figures.png")
        os.symlink(self.victim, planted)
        r = self.make_report()
        self.assertEqual(r.returncode, 0, r.stderr)
        self.assertFalse(os.path.islink(planted))
        self.assert_victim_untouched()

    def test_a_link_or_fifo_where_a_file_goes_is_refused(self):
        folder = os.path.join(self.root, "folder")
        os.makedirs(folder)
        os.symlink(self.victim, os.path.join(folder, "a.png.tmp"))
        with self.assertRaisesRegex(UnsafeFileError, "a.png.tmp: a symbolic link"):
            write_bytes(os.path.join(folder, "a.png"), b"x")
        os.mkfifo(os.path.join(folder, "b.png"))
        with self.assertRaisesRegex(UnsafeFileError, "b.png: not a regular file"):
            write_bytes(os.path.join(folder, "b.png"), b"x")
        os.symlink(folder, os.path.join(self.root, "linked"))
        with self.assertRaisesRegex(UnsafeFileError, "its folder is a symbolic link"):
            write_bytes(os.path.join(self.root, "linked", "c.png"), b"x")
        self.assert_victim_untouched()

    def test_a_ply_header_declaring_1e8_vertices_exits_2(self):
        path = os.path.join(self.out, "profile.ply")
        with open(path) as f:
            text = f.read()
        with open(path, "w") as f:
            f.write(text.replace("element vertex 300", "element vertex 100000000"))
        r = self.make_report()
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("profile.ply: the header declares 100000000 vertices but the file holds 300 lines", r.stderr)

    def test_a_time_of_1e309_exits_2_naming_it(self):
        path = os.path.join(self.out, "readings.csv")
        with open(path) as f:
            lines = f.read().split("\n")
        lines[1] = "1e309" + lines[1][lines[1].index(","):]
        with open(path, "w") as f:
            f.write("\n".join(lines))
        r = self.make_report()
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertIn("a t_s that is not a finite number", r.stderr)
        self.assertNotIn("Traceback", r.stderr)

    def test_a_garbage_scene_exits_2_without_a_traceback(self):
        with open(os.path.join(self.out, "scene.json"), "w") as f:
            f.write('{"sensors": 7, "objects": "x"}')
        r = self.make_report()
        self.assertEqual(r.returncode, 2, r.stderr)
        self.assertNotIn("Traceback", r.stderr)

    def test_a_zones_folder_outside_zones_is_refused(self):
        from proxsim_report.viewer_page import zones_viewer_data
        os.makedirs(os.path.join(self.out, "zones"))
        with open(os.path.join(self.out, "zones", "columns.json"), "w") as f:
            f.write('{"sensors": {"s": {"folder": "/etc", "zones": [1, 1]}}}')
        run = types.SimpleNamespace(out_dir=self.out, sensors=[types.SimpleNamespace(name="s", index=0)])
        with self.assertRaisesRegex(RunError, "folder '/etc' is not a folder name inside zones/"):
            zones_viewer_data(run)


if __name__ == "__main__":
    unittest.main()
