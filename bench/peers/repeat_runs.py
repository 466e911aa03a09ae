"""Repeating two codes' runs in alternation and tabulating their times
(the races' `--repeat-cheapest`: race_repeat.py here and in moordyn/)."""
import statistics


def repeat_alternating(name, runs, n):
    """Calls the two callables `runs` (each returns a time in s) n times,
    in alternation; (least, median) of each, printing every pair."""
    times = ([], [])
    for k in range(n):
        for code in (0, 1):
            times[code].append(runs[code]())
        print(name, k, times[0][-1], times[1][-1], flush=True)
    return [min(t) for t in times], [statistics.median(t) for t in times]


def table_row(name, texts, least, median):
    """The markdown row of one problem: its two runs, their least and
    median times and the ratios (the first code's over the second's)."""
    return "| %s | %s | %s | %.3f / %.3f | %.3f / %.3f | **%.2f** | %.2f |" % (
        name, texts[0], texts[1], least[0], median[0], least[1], median[1],
        least[0] / least[1], median[0] / median[1])


def write_table(path, lines):
    """Writes the table's lines to `path` and prints them."""
    text = "\n".join(lines) + "\n"
    print(text)
    with open(path, "w") as f:
        f.write(text)
