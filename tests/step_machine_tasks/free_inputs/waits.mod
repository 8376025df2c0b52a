! Task 1: waits on free inputs (chosen where read: each try a choice) and on shared
! data, one wait timed with a flag.
MODULE T1
  PERS num shared := 0;
  VAR num seen := 0;
  VAR bool late := FALSE;
  PROC main()
    WHILE TRUE DO
      WaitUntil DInput(di_free) = 1 AND shared < 2;
      seen := (seen + 1) MOD 2;
      WaitUntil di_other = 1 \MaxTime:=3 \TimeFlag:=late;
    ENDWHILE
  ENDPROC
ENDMODULE
