#!/usr/bin/python3
"""Counts the unique test cases in a catkin test-results folder and prints the suite's summary line.

Usage: test_summary.py RESULTS_DIR   (scripts/test.sh passes <workspace>/build/test_results)

Why not catkin_test_results' own "Summary": it adds each file's counts from the root element and from every
<testsuite> below it, so a gtest file (<testsuites tests=N><testsuite tests=N>) counts every case twice;
and a rostest file holds one wrapper entry per <test> tag ("did the test run and write its results"),
while the test's own cases are in its rosunit-*.xml beside it. Here every <testcase> element is read once:
  - a case is failed if it holds <failure> or <error>, skipped if it holds <skipped> (gtest's GTEST_SKIP,
    pytest's skip and xfail) or gtest did not run it (status="notrun": DISABLED_), passed otherwise;
  - a rostest wrapper entry that passed is not counted (its test's cases are); one that failed (the test
    timed out, crashed before writing its results, a fixture node did not start) counts as one failure;
  - an unreadable result file counts as one failure (catkin writes MISSING-*.xml, a failure, when a test
    wrote none);
  - a parameter variation is a gtest TEST_P/TYPED_TEST instance (value_param / type_param attribute) or a
    pytest parametrize id ("name[id]"): each is a case of its own, and their number is said.
The last line is "tests: N passed, N failed, N skipped" (CI reads it); the exit status is 1 when any case
failed or none was found, 0 otherwise. Standard library only (Debian's /usr/bin/python3).
"""
import os
import sys
import xml.etree.ElementTree as ET

# rostest's runner names its wrapper entries with this class (rostest/runner.py, the RosTest TestCase).
ROSTEST_WRAPPER_CLASSES = ("rostest.runner.RosTest", "rostest.rostest.RosTest")
RANK = {"passed": 0, "skipped": 1, "failed": 2}


def case_status(case):
    """passed, failed or skipped, and the failure's message (empty unless failed)."""
    for tag in ("failure", "error"):
        bad = case.find(tag)
        if bad is not None:
            message = bad.get("message") or (bad.text or "").strip().splitlines()[:1]
            if isinstance(message, list):
                message = message[0] if message else ""
            return "failed", f"{tag}: {message}"
    if case.find("skipped") is not None or case.get("status") == "notrun" or case.get("result") in (
            "skipped", "suppressed"):
        return "skipped", ""
    return "passed", ""


def kind_of(file_name):
    """The test type, from catkin's file naming: gtest-*, pytest-*, rostest-*, rosunit-*, MISSING-*."""
    stem = os.path.basename(file_name)
    for kind in ("gtest", "pytest", "rostest", "rosunit", "MISSING", "nosetests"):
        if stem.startswith(kind + "-"):
            return kind
    return "other"


def is_parameter_variation(case, kind):
    if case.get("value_param") is not None or case.get("type_param") is not None:
        return True  # gtest writes these attributes for TEST_P and TYPED_TEST(_P) instances
    name = case.get("name") or ""
    return kind == "pytest" and name.endswith("]") and "[" in name


def is_rostest_wrapper(case, kind):
    return kind == "rostest" and (case.get("classname") or "").endswith(ROSTEST_WRAPPER_CLASSES)


def summarize(results_dir):
    cases = {}  # (file, classname, name) -> [status, message, kind, variation]
    wrappers = {"passed": 0, "failed": 0, "skipped": 0}
    unreadable = []
    files = []
    for root, _, names in os.walk(results_dir):
        files += [os.path.join(root, n) for n in names if n.endswith(".xml")]
    for path in sorted(files):
        rel = os.path.relpath(path, results_dir)
        kind = kind_of(path)
        try:
            tree = ET.parse(path)
        except (ET.ParseError, OSError) as e:
            unreadable.append((rel, str(e)))
            continue
        for case in tree.getroot().iter("testcase"):
            status, message = case_status(case)
            if is_rostest_wrapper(case, kind):
                wrappers[status] += 1
                if status != "failed":
                    continue  # the test's own cases are counted from its rosunit-*.xml
            key = (rel, case.get("classname") or "", case.get("name") or "")
            entry = [status, message, kind, is_parameter_variation(case, kind)]
            if key not in cases or RANK[status] > RANK[cases[key][0]]:
                cases[key] = entry  # one case written twice (pytest: a call and a teardown error): the worst
    return files, cases, wrappers, unreadable


def main(argv):
    if len(argv) != 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    results_dir = argv[1]
    files, cases, wrappers, unreadable = summarize(results_dir)
    counts = {"passed": 0, "failed": 0, "skipped": 0}
    by_kind = {}
    variations = {}
    for (rel, classname, name), (status, message, kind, variation) in sorted(cases.items()):
        counts[status] += 1
        by_kind[kind] = by_kind.get(kind, 0) + 1
        if variation:
            variations[kind] = variations.get(kind, 0) + 1
        if status == "failed":
            print(f"FAILED  {rel}: {classname}.{name}  ({message})")
    for rel, error in unreadable:
        print(f"FAILED  {rel}: unreadable result file ({error})")
        counts["failed"] += 1
    total = sum(counts.values())
    kinds = ", ".join(f"{n} {k}" for k, n in sorted(by_kind.items()))
    print(f"result files: {len(files)}; unique test cases: {total} ({kinds})")
    gtest_p = variations.get("gtest", 0) + variations.get("rosunit", 0)
    pytest_p = variations.get("pytest", 0)
    print(f"parameter variations among them: {sum(variations.values())} ({gtest_p} gtest TEST_P/TYPED_TEST "
          f"instances, {pytest_p} pytest parametrize ids); {total - sum(variations.values())} distinct tests")
    print(f"rostest wrapper entries not counted: {wrappers['passed'] + wrappers['skipped']} (each repeats its "
          f"test's own result; {wrappers['failed']} failed wrapper(s) counted as failures above)")
    if total == 0:
        print("no test results found in " + results_dir)
    print(f"tests: {counts['passed']} passed, {counts['failed']} failed, {counts['skipped']} skipped")
    return 1 if counts["failed"] or total == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
