"""labels_test.py BUILD_DIR [expected label...]: every ctest of the build
carries exactly one of `fast` and `slow`, no label outside SPEC §12's six,
and each expected label (gpu when the Vulkan backend is built, mpi with MPI,
fuzz always) on at least one test (cmake/test_labels.cmake)."""
import json
import subprocess
import sys

ALLOWED = {"fast", "slow", "gpu", "mpi", "browser", "fuzz"}
build, expected = sys.argv[1], set(sys.argv[2:])
listing = json.loads(subprocess.run(["ctest", "--show-only=json-v1"], cwd=build, check=True,
                                    capture_output=True, text=True).stdout)
problems, seen = [], set()
for test in listing["tests"]:
    labels = next((p["value"] for p in test.get("properties", []) if p["name"] == "LABELS"), [])
    seen.update(labels)
    speed = [label for label in labels if label in ("fast", "slow")]
    if len(speed) != 1:
        problems.append(f"{test['name']}: labels {labels} (needs exactly one of fast, slow)")
    for label in set(labels) - ALLOWED:
        problems.append(f"{test['name']}: label {label!r} is not one of {sorted(ALLOWED)}")
for label in sorted(expected - seen):
    problems.append(f"no test is labelled {label}")
print(f"{len(listing['tests'])} tests, labels {sorted(seen)}")
for line in problems[:40]:
    print(line)
sys.exit(1 if problems else 0)
