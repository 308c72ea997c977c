"""Runs pvbatch (or mpiexec pvbatch) with the plugin and ParaView's private Python, for the
drivers Debian's /usr/bin/python3 runs. A window the X server refused ('bad X server
connection', which a loaded machine's Xvfb does now and then, as the project's own window tests
see) is tried again, twice at most; any other failure is final."""
import os
import subprocess
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def environment():
    env = dict(os.environ)
    env["PYTHONPATH"] = os.environ["ART_PV_PYTHONPATH"]
    env["PV_PLUGIN_PATH"] = os.environ["ART_PV_PLUGIN_DIR"]
    # mpiexec as root, and more ranks than cores (CI has 2): ranks waiting in a collective yield.
    env.update(OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1",
               OMPI_MCA_rmaps_base_oversubscribe="1", OMPI_MCA_mpi_yield_when_idle="1")
    return env


def pvbatch(script, *args, ranks=1, timeout=900, echo=False):
    """Runs the script; returns its stdout, or exits with its stderr's end when it fails."""
    cmd = [os.environ["ART_PVBATCH"], script, *args]
    if ranks > 1:
        cmd = [os.environ["ART_MPIEXEC"], "-np", str(ranks), *cmd]
    for attempt in range(3):
        run = subprocess.run(cmd, env=environment(), capture_output=True, text=True, timeout=timeout)
        if run.returncode == 0 or "bad X server connection" not in run.stderr:
            break
        print("(the X server refused a window; again)", file=sys.stderr)
    if echo:
        print(run.stdout, end="")
    if run.returncode != 0:
        sys.exit("%s failed (%d):\n%s%s" % (" ".join(cmd), run.returncode, run.stdout[-2000:], run.stderr[-3000:]))
    return run.stdout
