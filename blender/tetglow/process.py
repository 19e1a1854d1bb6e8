"""Runs `tetglow render` and reads its progress lines (docs/USAGE.md: one line per tenth of the
way when stderr is not a terminal)."""
import queue
import re
import subprocess
import threading

PASS = re.compile(r'pass (\d+)(?: of (\d+))?, ([\d.]+) s, ([\d.]+) s left, (?:noise ([0-9.eE+-]+)|noise: from)')


def parse_progress(line):
    """(passes, passes planned or None, fraction done, noise or None) of a progress line, or None."""
    m = PASS.search(line)
    if m is None:
        return None
    done, planned, spent, left, noise = m.groups()
    spent, left = float(spent), float(left)
    fraction = spent / (spent + left) if spent + left > 0 else 0.0
    return int(done), (int(planned) if planned else None), fraction, (float(noise) if noise else None)


def is_warning(line):
    return 'warning' in line.lower()


class Render:
    """The child process, its stderr lines arriving on a queue; stdout is kept for errors."""

    def __init__(self, argv, cwd):
        self.proc = subprocess.Popen(argv, cwd=cwd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                     stdin=subprocess.DEVNULL, text=True, errors='replace')
        self.lines = queue.Queue()
        self._reader = threading.Thread(target=self._read, daemon=True)
        self._reader.start()

    def _read(self):
        for line in self.proc.stdout:
            self.lines.put(line.rstrip('\n'))
        self.lines.put(None)

    def next_line(self, timeout):
        """The next line; '' when none came within timeout; None at the end of the output."""
        try:
            return self.lines.get(timeout=timeout)
        except queue.Empty:
            return ''

    def stop(self):
        """Cancel: SIGTERM (tetglow stops after the pass), SIGKILL if it lingers."""
        if self.proc.poll() is None:
            self.proc.terminate()
            try:
                self.proc.wait(timeout=5)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
