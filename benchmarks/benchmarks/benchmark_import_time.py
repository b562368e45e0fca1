"""Import time of the package (a fresh interpreter each sample)."""


class ImportSuite:
    def timeraw_import_rgbz_fast(self):
        return "import rgbz_fast"
