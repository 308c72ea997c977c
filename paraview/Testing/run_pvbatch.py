"""run_pvbatch.py SCRIPT [ARGS]: one pvbatch test (see pvrun.py); its output is shown."""
import sys

import pvrun

pvrun.pvbatch(sys.argv[1], *sys.argv[2:], echo=True)
