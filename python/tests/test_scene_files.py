"""A scene file's ``model = "..."`` gets the same file checks as ``model=``: a file that is not
a regular file (a FIFO, ``/dev/zero``) is refused before it is opened, and one above the size
limit is refused as ``model=`` refuses it (issue 35: ``/dev/zero`` grew past 2.5 GB holding the
GIL, a FIFO hung for good, a 10 MB model was accepted). The check is the library's (the scene
crate's bounded reader, used by ``walker::setup``); each call runs in a child process with a
time and a memory bound, so that a regression is a failure here, not a hang or an exhausted
machine."""

import os
import resource
import subprocess
import sys
import textwrap

import pytest
from conftest import MODELS

# A refusal reads at most the file's metadata: milliseconds. 20 s covers the child's start
# (importing NumPy and the module) on a loaded machine; a FIFO that is opened never returns.
CHILD_SECONDS = 20.0

# The child may hold 2 GB of address space: the interpreter, NumPy and the module's threads
# take a few hundred MB; a read of /dev/zero would pass the bound in about a second.
CHILD_BYTES = 2 << 30


def describe_in_child(scene):
    """Runs ``sw.describe(scene=scene)`` in a child process; returns (outcome, message)."""
    code = textwrap.dedent(f"""
        import slippery_walker as sw
        try:
            sw.describe(scene={str(scene)!r})
            print("ok")
        except ValueError as e:
            print("ValueError")
            print(e)
    """)

    def limit():
        resource.setrlimit(resource.RLIMIT_AS, (CHILD_BYTES, CHILD_BYTES))

    run = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=CHILD_SECONDS, preexec_fn=limit)
    assert run.returncode == 0, run.stderr[-2000:]
    outcome, _, message = run.stdout.partition("\n")
    return outcome, message.strip()


def scene_naming(tmp_path, model):
    scene = tmp_path / "scene.toml"
    scene.write_text(f'name = "hostile"\nmodel = "{model}"\n')
    return scene


def test_a_scene_naming_dev_zero_as_its_model_is_refused_without_reading_it(tmp_path):
    outcome, message = describe_in_child(scene_naming(tmp_path, "/dev/zero"))
    assert outcome == "ValueError", message
    assert message.startswith(("invalid scene:", "invalid model:")), message
    assert "/dev/zero" in message, message


def test_a_scene_naming_a_fifo_as_its_model_is_refused_without_opening_it(tmp_path):
    fifo = tmp_path / "model.toml"
    os.mkfifo(fifo)
    outcome, message = describe_in_child(scene_naming(tmp_path, fifo))
    assert outcome == "ValueError", message
    assert message.startswith(("invalid scene:", "invalid model:")), message
    assert "model.toml" in message, message


def test_a_scene_naming_a_model_above_the_size_limit_is_refused_as_model_is(tmp_path):
    big = tmp_path / "big.toml"
    text = (MODELS / "compass-gait.toml").read_text()
    big.write_text(text + "#" * (10 << 20) + "\n")  # 10 MB, a comment after a valid model
    outcome, message = describe_in_child(scene_naming(tmp_path, big))
    assert outcome == "ValueError", message
    assert message.startswith(("invalid scene:", "invalid model:")), message
    assert "big.toml" in message, message


def test_model_equals_refuses_the_same_files(tmp_path):
    # The reference the scene's `model` must match (this holds before the library's change).
    import slippery_walker as sw

    fifo = tmp_path / "fifo.toml"
    os.mkfifo(fifo)
    big = tmp_path / "big.toml"
    big.write_text("#" * (10 << 20))
    for path in ("/dev/zero", fifo, big):
        with pytest.raises(ValueError, match=r"^invalid model: "):
            sw.describe(model=path)
