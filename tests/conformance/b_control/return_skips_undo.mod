MODULE MainModule
  ! Tests: a normal RETURN does not run the routine's UNDO handler.
  PROC main()
    Sub;
    TPWrite "back in main";
  ENDPROC

  PROC Sub()
    TPWrite "in Sub";
    RETURN;
  UNDO
    TPWrite "undo must not run";
  ENDPROC
ENDMODULE
