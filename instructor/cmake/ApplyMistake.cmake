# cmake -DPATCH_PROGRAM=patch -DREFERENCE=solution/x.cpp -DMISTAKE=instructor/tests/mistakes/x/y.patch -DOUTPUT=y.cpp -P ApplyMistake.cmake
#
# Writes OUTPUT: the reference lab file with one catalogued mistake applied.
# A patch that no longer applies exactly (the reference changed under it) is
# an error that names the patch, so a proof always tests today's reference.
file(READ ${MISTAKE} text)
string(FIND "${text}" "\n--- " diff_at)
if(diff_at EQUAL -1)
  message(FATAL_ERROR "${MISTAKE}: no diff in it (expected 'Mistake:' and 'Symptom:' lines, then `diff -u` output)")
endif()
string(SUBSTRING "${text}" 0 ${diff_at} header)
if(NOT header MATCHES "^Mistake: [^\n]+\nSymptom: [^\n]+")
  message(FATAL_ERROR "${MISTAKE}:1: the patch must start with a 'Mistake: ...' line and a 'Symptom: ...' line")
endif()
get_filename_component(folder ${OUTPUT} DIRECTORY)
file(MAKE_DIRECTORY ${folder})
execute_process(
  COMMAND ${PATCH_PROGRAM} --fuzz=0 --force --silent --no-backup-if-mismatch --reject-file=- -o ${OUTPUT}.new ${REFERENCE} ${MISTAKE}
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE output)
if(NOT result EQUAL 0)
  file(REMOVE ${OUTPUT}.new)
  message(FATAL_ERROR "${MISTAKE} no longer applies to ${REFERENCE}: ${output}"
                      "Write the mistake again against today's reference (instructor/docs/instructors.md, 'Add a catalogued mistake').")
endif()
file(RENAME ${OUTPUT}.new ${OUTPUT})
