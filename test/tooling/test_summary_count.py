"""scripts/test_summary.py, the suite's summary line, on result files written as gtest 1.12 (Debian 12),
pytest, rostest (rostest/runner.py: one RosTest entry per <test> tag) and catkin's run_tests.py (MISSING-*.xml)
write them: each test case counted once,
rostest's wrapper entries not at all unless they failed, parameter variations said, and the exit status
non-zero on any failure, error, unreadable file or empty folder."""
import os
import subprocess
import sys

SCRIPT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "scripts", "test_summary.py")

# gtest: <testsuites> over <testsuite>, both with tests= (catkin_test_results adds both: 2 x 3 here).
GTEST = """<?xml version="1.0" encoding="UTF-8"?>
<testsuites tests="4" failures="0" disabled="1" errors="0" name="AllTests">
  <testsuite name="Winch" tests="2" failures="0" disabled="0" skipped="0" errors="0">
    <testcase name="SpeedRamps" status="run" result="completed" classname="Winch" />
    <testcase name="LinePull" status="run" result="completed" classname="Winch" />
  </testsuite>
  <testsuite name="Sizes/Grid" tests="2" failures="0" disabled="1" skipped="0" errors="0">
    <testcase name="Converges/0" value_param="10" status="run" result="completed" classname="Sizes/Grid" />
    <testcase name="DISABLED_Slow" status="notrun" result="suppressed" classname="Sizes/Grid" />
  </testsuite>
</testsuites>
"""
GTEST_FAILING = """<?xml version="1.0" encoding="UTF-8"?>
<testsuites tests="2" failures="1" disabled="0" errors="0" name="AllTests">
  <testsuite name="Seabed" tests="2" failures="1" disabled="0" skipped="1" errors="0">
    <testcase name="Rests" status="run" result="completed" classname="Seabed">
      <failure message="Expected: (error) &lt; (0.01), actual: 0.02 vs 0.01" type=""><![CDATA[test_seabed.cpp:12]]></failure>
    </testcase>
    <testcase name="Grid" status="run" result="skipped" classname="Seabed"><skipped message="no grid" /></testcase>
  </testsuite>
</testsuites>
"""
PYTEST = """<?xml version="1.0" encoding="utf-8"?><testsuites><testsuite name="pytest" errors="0" failures="0"
 skipped="1" tests="4"><testcase classname="test.test_presets" name="test_preset_runs_to_its_end[default.yaml]" time="1.0" />
<testcase classname="test.test_presets" name="test_preset_runs_to_its_end[tms.yaml]" time="1.0" />
<testcase classname="test.test_presets" name="test_statics" time="1.0" />
<testcase classname="test.test_presets" name="test_later" time="0.0"><skipped type="pytest.skip" message="later" /></testcase>
</testsuite></testsuites>
"""
PYTEST_TEARDOWN_ERROR = """<?xml version="1.0" encoding="utf-8"?><testsuites><testsuite name="pytest" errors="1" failures="0"
 skipped="0" tests="2"><testcase classname="test.test_node" name="test_a" time="1.0" />
<testcase classname="test.test_node" name="test_a" time="0.1"><error message="failed on teardown">boom</error></testcase>
</testsuite></testsuites>
"""
# rostest: one wrapper entry per <test> tag; the test's own cases in rosunit-<test-name>.xml.
ROSTEST = """<?xml version="1.0" encoding="utf-8"?><testsuite name="rostest" tests="1" errors="0" failures="0" time="9.1">
<testcase classname="rostest.runner.RosTest" name="testtest_winch_node" time="9.0"></testcase></testsuite>
"""
ROSUNIT = """<?xml version="1.0" encoding="UTF-8"?>
<testsuites tests="2" failures="0" disabled="0" errors="0" name="AllTests">
  <testsuite name="WinchNode" tests="2" failures="0" disabled="0" skipped="0" errors="0">
    <testcase name="PaysOut" status="run" result="completed" classname="WinchNode" />
    <testcase name="HaulsIn" status="run" result="completed" classname="WinchNode" />
  </testsuite>
</testsuites>
"""
ROSTEST_TIMED_OUT = """<?xml version="1.0" encoding="utf-8"?><testsuite name="rostest" tests="1" errors="1" failures="0" time="60">
<testcase classname="rostest.runner.RosTest" name="testtest_slow" time="60"><error type="" message="test [test_slow] timed out">
</error></testcase></testsuite>
"""
# catkin's run_tests.py, when a test wrote no result file.
MISSING = """<?xml version="1.0" encoding="UTF-8"?>
<testsuite tests="1" failures="1" time="1" errors="0" name="test_crash.missing_result">
  <testcase name="test_ran" status="run" time="1" classname="Results">
    <failure message="Unable to find test results for test_crash.xml" type=""/>
  </testcase>
</testsuite>
"""


def summarize(tmp_path, files):
    results = tmp_path / "test_results" / "cable_dynamics"
    results.mkdir(parents=True)
    for name, text in files.items():
        (results / name).write_text(text)
    done = subprocess.run(["/usr/bin/python3", SCRIPT, str(tmp_path / "test_results")], capture_output=True,
                          text=True, timeout=60)
    print(done.stdout, done.stderr)
    return done.returncode, done.stdout.strip().splitlines()


def test_every_case_counted_once_and_wrappers_not_at_all(tmp_path):
    status, lines = summarize(tmp_path, {"gtest-test_winch.xml": GTEST, "pytest-presets.xml": PYTEST,
                                         "rostest-test_winch.xml": ROSTEST, "rosunit-test_winch_node.xml": ROSUNIT})
    assert status == 0
    # 4 gtest (one disabled: skipped) + 4 pytest (one skipped) + 2 rosunit; the wrapper not counted.
    assert lines[-1] == "tests: 8 passed, 0 failed, 2 skipped"
    assert "unique test cases: 10 (4 gtest, 4 pytest, 2 rosunit)" in "\n".join(lines)
    assert "parameter variations among them: 3 (1 gtest TEST_P/TYPED_TEST instances, 2 pytest parametrize ids)" \
        in "\n".join(lines)
    assert "rostest wrapper entries not counted: 1" in "\n".join(lines)


def test_a_failure_fails_the_summary_and_is_named(tmp_path):
    status, lines = summarize(tmp_path, {"gtest-test_seabed.xml": GTEST_FAILING})
    assert status == 1
    assert lines[-1] == "tests: 0 passed, 1 failed, 1 skipped"
    assert any(line.startswith("FAILED") and "Seabed.Rests" in line and "0.02 vs 0.01" in line for line in lines)


def test_a_teardown_error_counts_the_case_once_as_failed(tmp_path):
    status, lines = summarize(tmp_path, {"pytest-node.xml": PYTEST_TEARDOWN_ERROR})
    assert status == 1
    assert lines[-1] == "tests: 0 passed, 1 failed, 0 skipped"


def test_a_timed_out_rostest_and_a_missing_result_are_failures(tmp_path):
    status, lines = summarize(tmp_path, {"rostest-test_slow.xml": ROSTEST_TIMED_OUT, "MISSING-test_crash.xml": MISSING,
                                         "gtest-test_winch.xml": GTEST})
    assert status == 1
    assert lines[-1] == "tests: 3 passed, 2 failed, 1 skipped"


def test_an_unreadable_file_is_a_failure(tmp_path):
    status, lines = summarize(tmp_path, {"gtest-test_cut.xml": GTEST[:200], "pytest-presets.xml": PYTEST})
    assert status == 1
    assert lines[-1] == "tests: 3 passed, 1 failed, 1 skipped"
    assert any("unreadable result file" in line for line in lines)


def test_no_results_is_a_failure(tmp_path):
    status, lines = summarize(tmp_path, {})
    assert status == 1
    assert lines[-1] == "tests: 0 passed, 0 failed, 0 skipped"


if __name__ == "__main__":
    sys.exit(subprocess.call([sys.executable, "-m", "pytest", "-q", __file__]))
