MODULE entry_option
  ! Tests: `rapidmc run --entry start` starts execution in the named
  ! parameterless procedure instead of main.
  PROC main()
    TPWrite "main";
  ENDPROC
  PROC start()
    TPWrite "start";
  ENDPROC
ENDMODULE
