#!/usr/bin/python3
"""Independent check of expected/fig12: done together with fig11 (same points, to_5 only)."""
import os, runpy, sys
here = os.path.dirname(os.path.abspath(__file__))
sys.argv = [sys.argv[0], os.path.join(here, "..", "fig11")]
runpy.run_path(os.path.join(here, "..", "fig11", "independent.py"), run_name="__main__")
