MODULE Handshake
  ! Written for the test (issue 28): of the AND, bReady = FALSE is a value the loaded code
  ! writes, and nCmd gets a computed write that might end its test: neither is taken as a
  ! client's, and as the computed value is always 0 here, the deadlock is found.
  PERS num nCmd := 0;
  PERS bool bReady := FALSE;

  PROC main()
    bReady := FALSE;
    nCmd := 0;
    nCmd := nCmd * 2;
    WaitUntil nCmd <> 0 AND bReady = FALSE;
  ENDPROC
ENDMODULE
