"""A search worker's memory as it starts, stage by stage (bench/distributed.py --start-memory).

RSS in MB (all, anonymous, file pages; Linux /proc) and the modules loaded, after each
stage: the process as it is, numpy, the distributed search's modules, the counters N=10
model built as a worker builds it (from the program's text), and its packed table; in a
plain process and in a Ray actor started as ``--workers`` starts them.  Nothing heavy is
imported at the top, so that the first stage is the bare process.
"""
import sys


def stages(bench: str) -> list:
    import tempfile
    from dataclasses import replace
    from pathlib import Path

    def now(stage: str) -> tuple:
        with open("/proc/self/status") as status:
            fields = dict(line.split(":", 1) for line in status)
        return (stage, *(int(fields[key].split()[0]) // 1024
                         for key in ("VmRSS", "RssAnon", "RssFile")), len(sys.modules))
    found = [now("start")]
    import numpy  # noqa: F401
    found.append(now("numpy"))
    import rapidmc.check.distributed.partition  # noqa: F401
    found.append(now("search modules"))
    sys.path.insert(0, bench)
    from check import counters_program          # (bench/check.py)
    from rapidmc import api
    from rapidmc.check.native import state_table
    path = Path(tempfile.mkdtemp()) / "counters.mod"
    path.write_text(counters_program(10, 4))
    options = api.CheckOptions()
    options = replace(options, reductions=replace(options.reductions, partial_order=False))
    system = api.prepare(api.load_program([str(path)]), [], options).system
    found.append(now("model"))
    state_table(system, packed=True)
    found.append(now("state table"))
    return found


def show(where: str, found: list) -> None:
    print(where + ": " + "; ".join(f"{stage} {rss} MB ({anon} anonymous, {files} file), "
                                   f"{modules} modules"
                                   for stage, rss, anon, files, modules in found))


if __name__ == "__main__":
    import logging
    bench = str(__import__("pathlib").Path(__file__).resolve().parent)
    show("plain process", stages(bench))
    import ray
    sys.path.insert(0, bench)
    from rapidmc.check.distributed.cluster import LOCAL_SYSTEM_CONFIG
    from rapidmc.check.distributed.search import WORKER_ENVIRONMENT
    ray.init(num_cpus=1, include_dashboard=False, logging_level=logging.ERROR,
             log_to_driver=False, _system_config=LOCAL_SYSTEM_CONFIG)
    probe = ray.remote(num_cpus=1, runtime_env=WORKER_ENVIRONMENT)(stages)
    show("Ray worker", ray.get(probe.remote(bench)))
    ray.shutdown()
