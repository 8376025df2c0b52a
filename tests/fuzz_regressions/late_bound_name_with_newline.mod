! expect: exit 1 [RMC301]
! A late-bound procedure name holding a newline ("\0A"): the run-time error's message
! shows it escaped, so the diagnostic stays one line (once: the line broke in two).
MODULE LateBoundNewline
  PROC main()
    %"a\0Ab"%;
  ENDPROC
ENDMODULE
