"""bench-myriapoda peers: missing packages, the MuJoCo scene's element counts, the ratios."""
import pytest

from bench_myriapoda.cli import main
from bench_myriapoda.harness import peers as P
from bench_myriapoda.harness.regress import EntryResult


def test_without_the_peer_packages_it_names_them_and_exits_2_writing_nothing(tmp_path, capsys, monkeypatch):
    monkeypatch.setattr(P, "missing_packages", lambda: ["mujoco", "pyelastica"])
    store = tmp_path / "r.sqlite"
    assert main(["peers", "--store", str(store)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and "pip install mujoco pyelastica" in err[0]
    assert not store.exists()


@pytest.mark.parametrize("points, tets", [(3, 816), (4, 2754)])
def test_mujoco_scene_has_the_element_count_of_our_chain(points, tets):
    mujoco = pytest.importorskip("mujoco")
    model = mujoco.MjModel.from_xml_string(P.mujoco_flex_xml(points))
    assert model.nflexelem == tets and model.nflex == P.FLEX_BLOCKS
    assert model.opt.timestep == pytest.approx(P.FLEX_DT)


def _result(name, sps):
    return EntryResult(name=name, steps_per_rep=100, repeats=3, steps_per_s=sps, spread=0.0,
                       reference_ops_per_s=1e8, reference_spread=0.0)


def test_ratios_pair_ours_with_the_peer_of_the_same_scene():
    entries = P.peer_entries()
    results = [_result("peer:mujoco-flex-816", 1000.0), _result("ours:fem-chain-816", 20000.0),
               _result("peer:pyelastica-snake", 10000.0), _result("ours:massspring-snake", 50000.0)]
    rows = {r["entry"]: r for r in P.ratios(entries, results)}
    mj = rows["peer:mujoco-flex-816"]
    assert mj["ours"] == "ours:fem-chain-816" and mj["speedup_steps"] == pytest.approx(20.0)
    assert rows["ours:fem-chain-816"]["ns_per_element_step"] == pytest.approx(1e9 / (20000.0 * 816))
    snake = rows["peer:pyelastica-snake"]
    assert snake["speedup_steps"] == pytest.approx(5.0)
    assert snake["realtime_factor"] == pytest.approx(10000.0 * 1e-4)
