MODULE MatchFromHmi
  ! Issue 28 (the gantry head task of the survey): the task clears the match flag and waits
  ! until the HMI answers 1 (match) or -1 (no match); the loaded code writes only 0, so only
  ! a client ends the wait (the two tests of one PERS joined by OR are one test).
  PERS num nCmdMatch := 0;
  VAR num retries := 0;
  PROC main()
    WHILE TRUE DO
      nCmdMatch := 0;
      WaitUntil nCmdMatch = 1 OR nCmdMatch = -1;
      IF nCmdMatch = -1 THEN
        retries := retries + 1;
        IF retries > 3 retries := 0;
      ENDIF
    ENDWHILE
  ENDPROC
ENDMODULE
