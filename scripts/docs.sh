#!/usr/bin/env bash
# The documentation's checks and the docs site (run by scripts/test.sh after the test suite; needs
# the build: the program for the checked commands and the --help reference, the Python package for
# its API page).
#
#   bash scripts/docs.sh            # every check, the notebook tutorials (nbclient), then the site
#                                   # in build/site (MkDocs, --strict) with the Doxygen C++
#                                   # reference in build/site/cpp-api; exit 1 if any check failed
#   bash scripts/docs.sh --update   # after changing the program, its options or data/: regenerate
#                                   # the generated pages and the checked examples' output, then
#                                   # check everything (read `git diff docs/` before committing)
#
# Each generated reference page is checked against what the program, the package or the data
# files give now; a stale one fails with the command that regenerates it. Every check runs even
# when an earlier one fails, so one run lists everything to fix.
set -uo pipefail
cd "$(dirname "$0")/.."
py=/usr/bin/python3
export PYTHONPATH="$PWD/build/python${PYTHONPATH:+:$PYTHONPATH}"
case "${1:-}" in
  "") ;;
  --update)
    $py tools/gen_cli_reference.py && $py tools/gen_python_api.py && $py tools/gen_parameter_sources.py \
      && $py tools/check_doc_commands.py --update || exit 1 ;;
  *) echo "docs.sh: unknown option '$1' (--update)" >&2; exit 2 ;;
esac
start=$SECONDS
failed=()
check() {  # check NAME COMMAND...: run it; on failure remember NAME, return 1 and go on
  local name=$1
  shift
  if "$@"; then return 0; fi
  failed+=("$name")
  return 1
}
check pages       $py tools/check_docs_pages.py              # no page over 400 lines outside validation/, no "sessions"
check cli         $py tools/gen_cli_reference.py --check     # every flag of every --help in the reference and a guide
check python-api  $py tools/gen_python_api.py --check        # the Python API page matches the built module
check parameters  $py tools/gen_parameter_sources.py --check # the parameter-source pages match data/
check examples    $py tools/check_doc_commands.py            # the guides' commands print what their pages show
check notebooks   $py tools/run_notebooks.py                 # the notebook tutorials run, each with its figures
# MkDocs --strict: a broken link or a missing page fails; then every link to a section must land.
site() {  # MkDocs' warnings (what broke) shown; its page list and jinja2's deprecation note left out
  mkdocs build --strict 2>&1 \
    | { grep -v '^INFO\|^  - \|^$\|jinja2/lexer.py\|self.current = next\|\.decode("unicode-escape")' || true; }
}
check site site \
  && check anchors $py tools/check_docs_pages.py --site build/site
# The C++ API reference from the headers (Doxyfile), published beside the site.
check doxygen doxygen Doxyfile \
  && rm -rf build/site/cpp-api && cp -r build/doxygen/html build/site/cpp-api
if [ ${#failed[@]} -gt 0 ]; then
  echo "docs: FAILED: ${failed[*]} ($((SECONDS - start)) s)" >&2
  exit 1
fi
echo "docs: every check passed; site in build/site (C++ API in build/site/cpp-api), $((SECONDS - start)) s"
