"""Build of the ssda extension (ssda._ssda) from the library's own sources.

pip install --no-build-isolation tools/python   (offline: setuptools and
numpy from the system). The extension compiles lib/*.c and one kernel set
(sse2 on x86-64, else portable; SSDA_KERNEL=portable|sse2 overrides: every
set gives the same results) with the binding in src/. CMake builds the same
module from the same sources with -DSSDA_BUILD_PYTHON=ON (tools/python/
CMakeLists.txt).
"""
import glob
import os
import platform
import re

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.normpath(os.path.join(HERE, "..", ".."))
LIB = os.path.join(ROOT, "lib")


def library_version():
    """SSDA_VERSION_MAJOR/MINOR/PATCH of include/ssda/ssda.h."""
    with open(os.path.join(ROOT, "include", "ssda", "ssda.h"), encoding="utf-8") as f:
        text = f.read()
    return ".".join(re.search(r"#define SSDA_VERSION_%s +(\d+)" % p, text).group(1)
                    for p in ("MAJOR", "MINOR", "PATCH"))


def kernel():
    k = os.environ.get("SSDA_KERNEL")
    if k:
        return k
    return "sse2" if platform.machine().lower() in ("x86_64", "amd64") else "portable"


KERNEL = kernel()
LIB_SOURCES = (sorted(glob.glob(os.path.join(LIB, "*.c"))) +
               [os.path.join(LIB, "kernel", "kernel_%s.c" % KERNEL)])


class BuildExt(build_ext):
    """Adds the library's sources (outside this directory) at build time:
    setup() arguments must be relative paths inside it, and relative paths
    with '..' would put objects outside build/."""

    def build_extension(self, ext):
        ext.sources = list(ext.sources) + [s for s in LIB_SOURCES if s not in ext.sources]
        super().build_extension(ext)

# SSDA_PY_BUILD_BASE: keep build files and egg-info there instead of here
# (the tests install from a read-only point of view of the source tree).
BASE = os.environ.get("SSDA_PY_BUILD_BASE")
OPTIONS = {"build": {"build_base": BASE}, "egg_info": {"egg_base": BASE}} if BASE else {}

setup(
    version=library_version(),
    options=OPTIONS,
    cmdclass={"build_ext": BuildExt},
    ext_modules=[Extension(
        "ssda._ssda",
        sources=sorted(glob.glob("src/*.c")),
        include_dirs=[os.path.join(ROOT, "include"), LIB],
        define_macros=[("SSDAPY_KERNEL", '"%s"' % KERNEL)],
        # export PyInit__ssda only (gcc, clang): the library stays inside
        extra_compile_args=[] if os.name == "nt" else ["-fvisibility=hidden"],
    )],
)
