MODULE MainModule
  ! Tests: EXIT leaves routines abnormally, so their UNDO handlers run (innermost first);
  ! follows the reference (section 4.5: UNDO runs on EXIT).
  PROC main()
    Outer;
    TPWrite "not reached";
  UNDO
    TPWrite "undo main";
  ENDPROC

  PROC Outer()
    Inner;
  UNDO
    TPWrite "undo Outer";
  ENDPROC

  PROC Inner()
    TPWrite "in Inner";
    EXIT;
  UNDO
    TPWrite "undo Inner";
  ENDPROC
ENDMODULE
