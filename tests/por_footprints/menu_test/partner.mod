MODULE Poller
  PERS bool waitForJob := TRUE;
  PERS num job := 0;
  VAR num done := 0;
  PROC main()
    WHILE done < 2 DO
      WHILE waitForJob DO              ! SHARED
        WaitTime 0.1;
      ENDWHILE
      TEST done                        ! LOCAL
      CASE 0:
        done := 1;
      DEFAULT:
        done := 2;
      ENDTEST
      job := 0;                        ! SHARED
      waitForJob := TRUE;              ! SHARED
    ENDWHILE
  ENDPROC
ENDMODULE
