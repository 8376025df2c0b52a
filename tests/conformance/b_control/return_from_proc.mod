MODULE MainModule
  ! Tests: RETURN in a procedure ends it at once; the caller continues after the call.
  PROC main()
    Sub;
    TPWrite "back in main";
  ENDPROC

  PROC Sub()
    TPWrite "in Sub";
    RETURN;
    TPWrite "not reached";
  ENDPROC
ENDMODULE
