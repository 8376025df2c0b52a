MODULE errno_in_test
  ! Tests: ERRNO can be dispatched on with TEST; ERR_OUTOFBND is raised for
  ! an index beyond the array and handled by its CASE.
  PROC main()
    VAR num a{2};
    VAR num i := 3;
    a{i} := 1;
    TPWrite "continued";
  ERROR
    TEST ERRNO
    CASE ERR_DIVZERO:
      TPWrite "division";
    CASE ERR_OUTOFBND:
      TPWrite "index out of bounds";
    DEFAULT:
      TPWrite "other";
    ENDTEST
    TRYNEXT;
  ENDPROC
ENDMODULE
