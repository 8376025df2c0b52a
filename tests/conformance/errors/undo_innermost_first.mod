MODULE undo_innermost_first
  ! Tests: when an error unwinds several routines, their UNDO handlers run
  ! innermost first; a routine that handles the error is not unwound.
  PROC inner()
    RAISE 9;
  UNDO
    TPWrite "undo inner";
  ENDPROC
  PROC middle()
    inner;
  UNDO
    TPWrite "undo middle";
  ENDPROC
  PROC outer()
    middle;
    TPWrite "outer continues";
  ERROR
    TRYNEXT;
  UNDO
    TPWrite "undo outer";
  ENDPROC
  PROC main()
    outer;
    TPWrite "end";
  ENDPROC
ENDMODULE
