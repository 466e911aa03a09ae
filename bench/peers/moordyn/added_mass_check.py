"""Why the race runs the steep wave without added mass (docs/method.md
§12.5, "Against MoorDyn"): MoorDyn's fairlead tension against stancf's
converged line on the steep-wave cable, with the deck's Ca = 1 and with
Ca = CaAx = 0 in both codes, with a tighter initial condition for
MoorDyn, and with EI = 1 N m^2 in both codes. Prints each error as the
race measures it (race.error: the largest difference after the ramp over
the reference's range) and the Fourier amplitudes of the difference.

Run through ./run.sh --added-mass-check (about 10 minutes).

stancf's reference here is 96 elements at dt 0.0125 s, which the race
shows within 0.006 % of its finer one; each variant has its own, since
Ca and EI change the line.
"""
import sys

import numpy as np

import race

PB = race.STEEP
BASE_DECK = race.deck_text


def deck_with(ca, ei=None, thresh=None):
    """race.deck_text with the line types' Ca = CaAx = `ca` ("deck": as
    the deck gives them), EI set if given, MoorDyn's threshIC set if
    given."""
    def text(pb, refine, dtm):
        out, section = [], None
        for line in BASE_DECK(pb, refine, dtm).splitlines(True):
            if line.startswith("---"):
                section = line.upper()
            fields = line.split()
            if section and "LINE TYPES" in section and fields and fields[0] in ("cable",
                                                                               "buoyant"):
                if ca != "deck":
                    fields[7] = fields[9] = ca
                if ei is not None:
                    fields[5] = ei
                line = "  ".join(fields) + "\n"
            out.append(line)
        text = "".join(out)
        if thresh is not None:
            text = text.replace("0.0001  threshIC\n", "%r  threshIC\n" % thresh)
            text = text.replace("200.0  TmaxIC\n", "1000.0  TmaxIC\n")
        return text
    return text


def difference(times, tensions, ref):
    """The difference from the reference at common times after the ramp."""
    rt, rv = ref
    index = {round(t, 6): k for k, t in enumerate(rt)}
    pairs = [(k, index[round(t, 6)]) for k, t in enumerate(times)
             if t >= PB.period - 1e-9 and round(t, 6) in index]
    a = tensions[[p[0] for p in pairs], 0]
    b = rv[[p[1] for p in pairs], 0]
    return a - b, b.max() - b.min()


def report(label, deck, segments_refine, dtm):
    """MoorDyn at `segments_refine` x NumSegs and step `dtm` against
    stancf's reference, both on `deck`."""
    race.deck_text = deck
    PB.without_added_mass = False
    try:
        ref = race.run_stancf(PB, 2, 0.0125)
        md = race.run_moordyn(PB, segments_refine, dtm)
    finally:
        race.deck_text = BASE_DECK
        PB.without_added_mass = True
    if ref is None or md is None:
        print("%s: a run failed" % label, flush=True)
        return
    series = (ref[1], ref[2])
    e, span = difference(md[2], md[3], series)
    error = race.error(md[2], md[3], series, PB)
    f = np.fft.rfftfreq(len(e), race.OUTPUT_DT)
    amp = 2.0 * np.abs(np.fft.rfft(e - e.mean())) / len(e)
    peaks = ", ".join("%.2f Hz: %.1f N" % (f[i], amp[i])
                      for i in sorted(np.argsort(amp)[-4:], key=lambda i: f[i]))
    print("%s: MoorDyn %d segments, dtM %g (initial condition %.0f s, tension %.1f N at "
          "t = 0.1 s, stancf's %.1f N): error %.4f %% of %.0f N (largest %.1f N, mean %.1f N); "
          "Fourier amplitudes %s" % (
              label, race.segments(PB, segments_refine), dtm, md[0], md[3][0, 0],
              ref[2][0, 0], 100 * error, span, np.abs(e).max(), e.mean(), peaks), flush=True)


def main():
    report("Ca = 1 (the deck's)", deck_with("deck"), 2, 2e-4)
    report("Ca = 1, threshIC 1e-6", deck_with("deck", thresh=1e-6), 2, 2e-4)
    report("Ca = 1, EI = 1 N m^2", deck_with("deck", ei="1.0"), 2, 2e-4)
    report("Ca = 0", deck_with("0.0"), 1, 8e-4)
    report("Ca = 0", deck_with("0.0"), 2, 2e-4)


if __name__ == "__main__":
    sys.exit(main())
