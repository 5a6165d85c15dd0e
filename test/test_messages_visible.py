"""cable_msgs is nested in the cable_dynamics repository: check rosmsg/rossrv find it in the devel space."""
import subprocess


def show(tool, name):
    return subprocess.run([tool, "show", name], check=True, capture_output=True, text=True, timeout=60).stdout


def test_cable_state_message_is_visible():
    text = show("rosmsg", "cable_msgs/CableState")
    assert "float64[] tension" in text
    assert "geometry_msgs/Vector3 load_force" in text


def test_services_are_visible():
    assert "float64[] positions" in show("rossrv", "cable_msgs/Reset")
    assert "float64[] M" in show("rossrv", "cable_msgs/GetModel")
    assert "bool paused" in show("rossrv", "cable_msgs/SetPaused")
