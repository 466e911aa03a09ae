"""Executors for the sweep tests: a local Dask cluster, and a Dask
executor that loses, on purpose, the worker of run 0. Importing it
imports dask.distributed, whose configuration defaults must be in place
before a test sets one of them (a `dask.config.set` block entered before
the import restores, at its end, a configuration without them)."""

from dask.distributed import Client, LocalCluster


def cluster(**kw):
    """A local Dask cluster of two single-threaded worker processes and
    its client."""
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                           dashboard_address=None, **kw)
    return cluster, Client(cluster)


class KillsTheWorkerOfRun0:
    """A Dask executor for the sweep that loses, on purpose, the worker
    holding run 0: run 0's task starts its run (made to last minutes) and
    ends its own process once the run has begun writing. Run 0 goes to one
    worker and every other run to the other, so no other run can be on the
    dying worker by chance: what fails does not depend on scheduling."""

    def __init__(self, client, duration=100.0):
        client.wait_for_workers(2)
        # Run 0's duration (s): long enough to be running when it dies.
        self.duration = duration
        self.client = client
        self.doomed, self.spared = sorted(client.scheduler_info()["workers"])[:2]

    def submit(self, fn, text, name, folder):
        if not folder.endswith("run_0000"):
            return self.client.submit(fn, text, name, folder, workers=[self.spared],
                                      allow_other_workers=False, pure=False)

        duration = self.duration

        def die_holding_run_0(fn, text, name, folder):
            import os
            import threading
            import time
            import stancf
            long = stancf.Scenario(text).with_values({"analysis.duration": duration}).text
            run = threading.Thread(target=fn, args=(long, name, folder), daemon=True)
            run.start()
            parent, me = os.path.split(folder)
            # Until the run has taken its folder (its lock appears beside it).
            while run.is_alive() and not any(me in f for f in os.listdir(parent)):
                time.sleep(0.001)
            os._exit(1)

        return self.client.submit(die_holding_run_0, fn, text, name, folder,
                                  workers=[self.doomed], allow_other_workers=False, pure=False)
