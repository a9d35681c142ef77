cmake_minimum_required(VERSION 3.19)
# The command line itself (cmake -P): -DVISSWEEP=<exe> -DSCENE=<json> -DVERSION=<x.y.z>
#  - `vissweep --version` prints the version and exits 0;
#  - every error of the option parser exits 2, like every other error of the tool, and says why.
execute_process(COMMAND "${VISSWEEP}" --version RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT out MATCHES "vissweep ${VERSION}")
  message(FATAL_ERROR "vissweep --version (${rc}): '${out}' '${err}'")
endif ()
execute_process(COMMAND "${VISSWEEP}" --help RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "vissweep --help exits ${rc}")
endif ()
execute_process(COMMAND "${VISSWEEP}" render --help RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT out MATCHES "docs/reference.md")
  message(FATAL_ERROR "vissweep render --help (${rc}) does not point at docs/reference.md: ${out}")
endif ()
# name | arguments (space-separated) | what stderr must say
set(cases
  "no subcommand||subcommand"
  "unknown subcommand|frobnicate|subcommand"
  "unknown option|render ${SCENE} -o x.png --no-such-option|no-such-option"
  "missing value|render ${SCENE} -o|-o"
  "out of range|render ${SCENE} -o x.png --width 0|width"
  "not a number|render ${SCENE} -o x.png --spp many|spp"
  "excluded pair|render ${SCENE} -o x.png --spp 4 --time-budget 2|excludes"
  "missing output|render ${SCENE}|output"
  # Non-finite numbers (issue 13, item 5): CLI11 parses them as doubles and PositiveNumber let
  # NaN and +inf through (a NaN budget was ignored, an infinite one rendered 2^30 spp).
  "NaN budget|render ${SCENE} -o x.png --time-budget nan|time-budget: Value nan is not a finite number"
  "infinite budget|render ${SCENE} -o x.png --time-budget inf|time-budget: Value inf is not a finite number"
  "overflowing budget|render ${SCENE} -o x.png --time-budget 1e999|Value 1e999 is not a finite number"
  "NaN frame budget|bench animation ${SCENE} --budget-per-frame nan|budget-per-frame: Value nan is not a finite number"
  "infinite budgets|bench convergence ${SCENE} --budgets 1,inf|budgets: Value inf is not a finite number"
  # Issue 13, item 9: the seed's bounds as integers, not a 309-digit double.
  "negative seed|render ${SCENE} -o x.png --seed -5|--seed: Value -5 not in range 0 to 2147483647"
  # Issue 35, class 7: every benchmark output is checked before the run (a JSON into a missing folder
  # was "written" after the run, exit 0; one that is a device or a folder too).
  "bench frames json folder|bench frames ${SCENE} --frames 1 --size 8 --json /nonexistent-folder/x.json|--json /nonexistent-folder/x.json: folder '/nonexistent-folder' does not exist"
  "bench stress json device|bench stress ${SCENE} --json /dev/full|--json /dev/full: exists and is not a regular file"
  "bench sweeps json folder|bench sweeps --json /nonexistent-folder/x.json|--json /nonexistent-folder/x.json: folder"
  "bench lightvolume json folder|bench lightvolume ${SCENE} --json /nonexistent-folder/x.json|--json /nonexistent-folder/x.json: folder"
  "bench overhead json folder|bench overhead ${SCENE} --json /nonexistent-folder/x.json|--json /nonexistent-folder/x.json: folder"
  "bench animation plot folder|bench animation ${SCENE} --plot /nonexistent-folder/p.png|--plot /nonexistent-folder/p.png: folder"
  "bench convergence csv folder|bench convergence ${SCENE} --csv /nonexistent-folder/c.csv|--csv /nonexistent-folder/c.csv: folder"
  "bench preview sheet folder|bench preview ${SCENE} --contact-sheet /nonexistent-folder/s.png|--contact-sheet /nonexistent-folder/s.png: folder")
foreach (c IN LISTS cases)
  string(REPLACE "|" ";" parts "${c}")
  list(LENGTH parts n)
  list(GET parts 0 name)
  if (n EQUAL 3)
    list(GET parts 1 argstr)
    list(GET parts 2 expect)
  else ()
    set(argstr "")
    list(GET parts 1 expect)
  endif ()
  separate_arguments(args UNIX_COMMAND "${argstr}")
  execute_process(COMMAND "${VISSWEEP}" ${args} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 2)
    message(FATAL_ERROR "${name} (vissweep ${argstr}): exit ${rc}, expected 2: ${out} ${err}")
  endif ()
  if (NOT err MATCHES "${expect}")
    message(FATAL_ERROR "${name} (vissweep ${argstr}): stderr does not mention '${expect}': ${err}")
  endif ()
  message(STATUS "${name}: exit 2, ${err}")
endforeach ()
