"""python3 -m attractor_workbench.atlas PROJECT.awb --item NAME --grid w=A:B:N [--grid v=C:D:M]
[--mask ...] [--smoothness K] [--scheduler ADDRESS | --workers K | --in-process] --json OUT

The certified regularity atlas of a curve item's family of schemes (issue 48); see _atlas.py.
In a script, attractor_workbench.atlas(item, grid, client=None) is the same; this module is
callable too, so `import attractor_workbench.atlas` does not hide that function.
"""

import sys
import types

from ._atlas import IN_PROCESS, main, parse_grid, run_atlas  # noqa: F401


class _CallableModule(types.ModuleType):
    def __call__(self, *args, **kwargs):
        return run_atlas(*args, **kwargs)


sys.modules[__name__].__class__ = _CallableModule

if __name__ == "__main__":
    sys.exit(main())
