# Which tree this is, unless -DWHITTED_MODE=... says otherwise:
#   instructor  the whole tree: solution/ (the reference labs) and instructor/
#               (hidden tests, grader, benchmark, proofs)
#   handout     the student's tree: the framework, labs/ and the public tests
# instructor/scripts/export-handout.sh writes "handout" here in the copy it makes.
set(WHITTED_DEFAULT_MODE instructor)
