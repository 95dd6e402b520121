"""The package explains itself: a docstring on every public name, and help(areagraph) reads."""

import inspect
import pydoc
import unittest

import areagraph


class DocsTest(unittest.TestCase):

    def test_every_public_name_has_a_docstring(self):
        self.assertTrue(areagraph.__doc__)
        for name in areagraph.__all__:
            value = getattr(areagraph, name)
            self.assertTrue(inspect.getdoc(value), name)
            if inspect.isclass(value):
                for member_name, member in vars(value).items():
                    if member_name.startswith("_") or not (
                            inspect.isfunction(member) or isinstance(member, property)):
                        continue
                    self.assertTrue(inspect.getdoc(member), name + "." + member_name)

    def test_help_reads_well(self):
        text = pydoc.render_doc(areagraph, renderer=pydoc.plaintext)
        for words in ("segment(map_path_or_array, resolution=0.05, origin=(0, 0), options=None, "
                      "**set)", "class AreaGraph", "route(self, start_xy, goal_xy)",
                      "class Store", "area_graph(self, map, version=None)"):
            self.assertIn(words, text)


if __name__ == "__main__":
    unittest.main()
