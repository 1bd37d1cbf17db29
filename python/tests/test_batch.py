"""rocking_q.batch against `rocking batch`: the same manifest (tests/batch_mixed_manifest.sh:
synthetic records, every kind of job) gives the same results file byte for byte, on any
number of threads; a finished batch resumed says so and leaves the file as it was; bad
manifests are refused with the command line's message."""
import subprocess
from pathlib import Path

import pytest

import rocking_q as rq
from conftest import CLI, SOURCE


@pytest.fixture(scope="module")
def mixed(tmp_path_factory):
    d = tmp_path_factory.mktemp("batch")
    subprocess.run([str(SOURCE / "tests" / "batch_mixed_manifest.sh"), CLI, str(d)], check=True)
    return d


def test_the_results_file_is_the_command_lines_byte_for_byte(mixed):
    cli_out = mixed / "cli.csv"
    subprocess.run([CLI, "batch", str(mixed / "m.csv"), "--jobs", "1", "--output", str(cli_out), "--quiet"],
                   check=True)
    rows = [l for l in cli_out.read_text().splitlines() if l and not l.startswith("#")]
    for jobs in (1, 2, 3):
        out = mixed / ("py%d.csv" % jobs)
        r = rq.batch(str(mixed / "m.csv"), output=str(out), jobs=jobs)
        assert out.read_bytes() == cli_out.read_bytes(), "jobs=%d" % jobs
        assert (r.jobs, r.failed, r.ran, r.already_complete) == (len(rows) - 1, 0, len(rows) - 1, False)
        assert r.threads == jobs


def test_a_finished_batch_resumed_is_left_as_it_was(mixed):
    out = mixed / "again.csv"
    rq.batch(str(mixed / "m.csv"), output=str(out), jobs=2)
    before = out.read_bytes()
    r = rq.batch(str(mixed / "m.csv"), output=str(out), jobs=2, resume=True)
    assert r.already_complete and r.ran == 0
    assert out.read_bytes() == before


def test_a_failing_row_is_reported_in_its_row_and_the_rest_run(mixed):
    m = mixed / "bad.csv"
    m.write_text("id,kind,record,unit,record_dt,alpha,p\n"
                 "a,simulate,records/sine1.txt,g,0.01,0.1,2\n"
                 "b,simulate,records/none.txt,g,0.01,0.1,2\n"
                 "c,simulate,records/sine1.txt,g,0.01,-0.1,2\n")
    out = mixed / "bad_out.csv"
    r = rq.batch(str(m), output=str(out), jobs=2)
    assert (r.jobs, r.failed) == (3, 2)
    cli_out = mixed / "bad_cli.csv"
    done = subprocess.run([CLI, "batch", str(m), "--output", str(cli_out), "--quiet"])
    assert done.returncode == 3
    assert out.read_bytes() == cli_out.read_bytes()


def test_bad_manifests_and_arguments_are_refused_with_the_command_lines_message(mixed, tmp_path):
    with pytest.raises(ValueError, match="cannot open the manifest"):
        rq.batch(str(tmp_path / "none.csv"), output=str(tmp_path / "o.csv"))
    bad = tmp_path / "unknown.csv"
    bad.write_text("record,alpha,mass\nr.txt,0.1,3\n")
    with pytest.raises(ValueError, match="unknown column 'mass'"):
        rq.batch(str(bad), output=str(tmp_path / "o.csv"))
    with pytest.raises(ValueError, match="an empty file name"):
        rq.batch(str(mixed / "m.csv"), output="")
    with pytest.raises(ValueError, match=r"jobs: must be between 1 and 4096 \(got 0\)"):
        rq.batch(str(mixed / "m.csv"), output=str(tmp_path / "o.csv"), jobs=0)
    with pytest.raises(TypeError):
        rq.batch(str(mixed / "m.csv"))  # output is required: a batch's rows go to a file
