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
