"""Issue 23's Python cases: one Simulation shared by threads, hostile inputs, out-of-range integers."""
import os
import threading

import pytest

import proxsim
from conftest import scenario


def test_one_simulation_stepped_and_reset_from_two_threads():
    # step() releases the GIL; without a lock per object a reset() beside it freed what the step used
    sim = proxsim.Simulation.builtin("paper")
    failures = []
    stop = threading.Event()

    def stepper():
        try:
            while not stop.is_set():
                try:
                    sim.step()
                except RuntimeError as error:  # the episode ended: the other thread resets it
                    assert "every sample" in str(error)
        except Exception as error:  # noqa: BLE001 - any other failure is the test's
            failures.append(error)

    def resetter():
        try:
            for _ in range(200):
                sim.reset()
                sim.truth()
                sim.summary()
                _ = sim.done, sim.t_s
        except Exception as error:  # noqa: BLE001
            failures.append(error)

    threads = [threading.Thread(target=stepper), threading.Thread(target=stepper), threading.Thread(target=resetter)]
    for t in threads:
        t.start()
    threads[2].join(timeout=120)
    stop.set()
    for t in threads:
        t.join(timeout=120)
    assert not any(t.is_alive() for t in threads), "a thread hung"
    assert failures == []


def _scenario_with_mesh(tmp_path, mesh_name, mesh_bytes):
    (tmp_path / mesh_name).write_bytes(mesh_bytes)
    path = tmp_path / "scene.yaml"
    path.write_text("proxsim: 1\nduration_s: 0.1\nrate_hz: 10\nscene:\n  objects:\n"
                    f"    - {{name: thing, mesh: {{file: {mesh_name}}}}}\n"
                    "sensors:\n  - {name: s, type: ideal, pose: {xyz_m: [0, 0, 1]}}\n")
    return str(path)


@pytest.mark.parametrize("name, data, message", [
    ("deep.gltf", b'{"asset":{"version":"2.0","extras":' + b"[" * 200000 + b"]" * 200000 + b"}}",
     "JSON nested deeper than 256"),
    ("deep.dae", b'<?xml version="1.0"?><COLLADA>' + b"<node>" * 50000 + b"</node>" * 50000 + b"</COLLADA>",
     "XML elements nested deeper than 256"),
    ("liar.off", b"OFF\n2000000000 1 0\n0 0 0\n", "OFF header declares"),
])
def test_hostile_meshes_raise_input_error_not_a_crash(tmp_path, name, data, message):
    with pytest.raises(proxsim.InputError) as error:
        proxsim.Simulation(_scenario_with_mesh(tmp_path, name, data))
    assert message in str(error.value)


def test_a_fifo_mesh_raises_at_once(tmp_path):
    fifo = tmp_path / "pipe.obj"
    os.mkfifo(fifo)
    path = tmp_path / "scene.yaml"
    path.write_text("proxsim: 1\nscene:\n  objects:\n    - {name: thing, mesh: {file: pipe.obj}}\n"
                    "sensors:\n  - {name: s, type: ideal, pose: {xyz_m: [0, 0, 1]}}\n")
    with pytest.raises(proxsim.InputError, match="not a regular file"):
        proxsim.Simulation(str(path))


@pytest.mark.parametrize("kwargs, message", [
    ({"seed": -1}, "seed: expected an int in [0, 2**64 - 1], got -1"),
    ({"seed": 2**64}, "seed: expected an int in [0, 2**64 - 1], got 18446744073709551616"),
    ({"threads": 0}, "threads: expected an int in [1, 256], got 0"),
    ({"threads": 2**70}, "threads: expected an int in [1, 256]"),
])
def test_out_of_range_integers_name_the_argument(kwargs, message):
    with pytest.raises(ValueError) as error:
        proxsim.Simulation(scenario("paper_dining_room.yaml"), **kwargs)
    assert message in str(error.value)
    with pytest.raises(ValueError, match="reset: seed"):
        proxsim.Simulation.builtin("paper").reset(seed=-5)


def test_a_seed_of_2_to_the_64_minus_1_is_accepted():
    assert proxsim.Simulation.builtin("paper", seed=2**64 - 1).seed == 2**64 - 1


def test_out_folder_is_locked_while_a_simulation_writes_it(tmp_path):
    out = str(tmp_path / "out")
    first = proxsim.Simulation.builtin("paper", out=out)
    with pytest.raises(proxsim.InputError, match="in use by pid"):
        proxsim.Simulation.builtin("paper", out=out)
    first.close()  # the files written, the folder is free
    proxsim.Simulation.builtin("paper", out=out).close()
