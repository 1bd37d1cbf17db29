#!/usr/bin/python3
"""Independent check of expected/fig12: fig11's script (same points, to_5 only), on fig12's files."""
import os, runpy, sys
here = os.path.dirname(os.path.abspath(__file__))
sys.argv = [sys.argv[0], here]
runpy.run_path(os.path.join(here, "..", "fig11", "independent.py"), run_name="__main__")
