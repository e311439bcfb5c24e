"""Runs a bundle through simrt and prints what test/Python/simrt.test checks."""
import sys

import simrt

with simrt.Bundle(sys.argv[1]) as bundle:
    print("scene", bundle.name, "range", bundle.range, "max_steps",
          bundle.max_steps)
    results = {}
    for strategy in ("simple", "hip"):
        with simrt.Session(bundle, strategy=strategy, backend="cpu") as session:
            session.run(10)
            results[strategy] = session.get("X")
            if strategy == "hip":
                print("hip on", session.device.split()[0])
                print("time", session.time)
                print("evaluations", session.evaluations())
                print("big steps", session.metrics()["big_steps"])
                # Integers of the buffer's size would be read as floats.
                import array
                try:
                    session.put("X", array.array("i", [1] * bundle.range))
                except ValueError as error:
                    print("put:", error)
    # simple takes 10 steps of 1: 0.99^10; hip three big steps of 4, 4 and 2
    # (the last one clamped to the end): 0.96^2 * 0.98.
    print("simple %.5f hip %.5f" % (results["simple"][0], results["hip"][0]))
    # The reference executor (docs/Reference.md) gives hip's numbers.
    with simrt.Session(bundle, strategy="hip", backend="reference") as session:
        session.run(10)
        print("reference", session.device, "%.5f" % session.get("X")[0],
              "evaluations", session.evaluations())
# A closed session or bundle says so instead of answering with zeros.
closed_bundle = simrt.Bundle(sys.argv[1])
closed = simrt.Session(closed_bundle, strategy="hip", backend="cpu")
closed.close()
closed_bundle.close()
for what, call in (("session time", lambda: closed.time),
                   ("bundle range", lambda: closed_bundle.range)):
    try:
        print(what, call())
    except simrt.Error as error:
        print(what + ":", error)
try:
    simrt.Bundle(sys.argv[1] + ".missing")
except simrt.Error as error:
    print("error:", error)
