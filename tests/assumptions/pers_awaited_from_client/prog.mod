MODULE Hmi
  ! the loaded code writes nCmdInput only 0: a PC or an HMI sets the command
  PERS num nCmdInput := 0;
  VAR num done := 0;
  PROC main()
    WHILE TRUE DO
      nCmdInput := 0;
      WaitUntil nCmdInput <> 0;
      IF nCmdInput = 1 THEN
        done := done + 1;
        IF done > 3 done := 0;
      ENDIF
    ENDWHILE
  ENDPROC
ENDMODULE
