MODULE MainModule
  ! Tests: WaitTime takes a num time; a string is a static type error.
  PROC main()
    TPWrite "must not run";
    WaitTime "1";
  ENDPROC
ENDMODULE
