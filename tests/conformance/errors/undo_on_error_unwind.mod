MODULE undo_on_error_unwind
  ! Tests: the UNDO handler of a routine runs when the routine is left
  ! abnormally because an error propagates out of it. (The caller's handler
  ! prints nothing, so the output does not depend on whether UNDO runs
  ! before or after that handler.)
  PROC work()
    TPWrite "work";
    RAISE 4;
  UNDO
    TPWrite "undo work";
  ENDPROC
  PROC main()
    work;
    TPWrite "after";
  ERROR
    TRYNEXT;
  ENDPROC
ENDMODULE
