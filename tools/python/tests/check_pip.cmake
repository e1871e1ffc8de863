# cmake -DPYTHON=<python3> -DSRC=<tools/python> -DWORK=<scratch dir> -P check_pip.cmake
# The binding installs offline with pip, as docs/python.md says:
# pip install --no-build-isolation into a scratch virtual environment that
# sees the system's packages (setuptools, numpy), build files kept under
# WORK (SSDA_PY_BUILD_BASE) so the source tree stays clean; then one search
# through the installed module.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}/build")
execute_process(COMMAND "${PYTHON}" -m venv --system-site-packages --without-pip "${WORK}/venv"
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "python -m venv failed")
endif()
set(ENV{SSDA_PY_BUILD_BASE} "${WORK}/build")
set(ENV{PIP_DISABLE_PIP_VERSION_CHECK} 1)
execute_process(COMMAND "${PYTHON}" -m pip --python "${WORK}/venv/bin/python" install -q
                        --no-build-isolation --no-index --no-cache-dir "${SRC}"
                RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "pip install --no-build-isolation ${SRC} failed")
endif()
execute_process(COMMAND "${WORK}/venv/bin/python" -c "
import numpy as np, ssda
assert ssda.__file__.startswith('${WORK}/venv/'), ssda.__file__
y, x = np.mgrid[0:64, 0:64]
a = ((x * x + 3 * y * y + x * y) >> 2).astype(np.uint8)  # README's texture
r = ssda.match(a, a[20:28, 37:45])
assert (r.x, r.y, r.sad, r.exact) == (37, 20, 0, True), r
import shutil, subprocess
if shutil.which('nm'):  # the module exports its init function only
    out = subprocess.run(['nm', '-D', '--defined-only', ssda._ssda.__file__],
                         capture_output=True, text=True, check=True).stdout
    assert [l.split()[-1] for l in out.splitlines()] == ['PyInit__ssda'], out
print('ssda', ssda.__version__, 'installed by pip:', r)
" WORKING_DIRECTORY "${WORK}" RESULT_VARIABLE rc)
if(rc)
  message(FATAL_ERROR "the pip-installed module failed")
endif()
