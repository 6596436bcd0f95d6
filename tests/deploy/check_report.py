"""A list of findings that a check adds to, printed as it goes."""


class Report:
    def __init__(self):
        self.failures = []
        self.skips = []

    def check(self, name, ok, why=""):
        """Records `name` as passed if `ok`, else as failed because of `why`."""
        if ok:
            print(f"ok    {name}")
        else:
            print(f"FAIL  {name}: {why}")
            self.failures.append(f"{name}: {why}")
        return ok

    def skip(self, name, why):
        print(f"skip  {name}: {why}")
        self.skips.append(f"{name}: {why}")
