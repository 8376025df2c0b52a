MODULE Menu
  ! A master's menu: TEST of an item of its own is independent of the poller (as a
  ! condition); TEST of the job the poller clears is not.
  PERS bool waitForJob := TRUE;
  PERS num job := 0;
  VAR num item := 0;
  VAR num rounds := 0;
  PROC main()
    WHILE rounds < 2 DO
      item := (item MOD 3) + 1;
      TEST item                          ! LOCAL
      CASE 1:
        rounds := rounds + 1;
      CASE 2, 3:
        job := item;                     ! SHARED
        waitForJob := FALSE;             ! SHARED
        WaitUntil waitForJob = TRUE;
      DEFAULT:
        rounds := 9;
      ENDTEST
      TEST job                           ! SHARED
      CASE 2:
        TPWrite "the poller has not cleared job 2";
      ENDTEST
    ENDWHILE
  ENDPROC
ENDMODULE
