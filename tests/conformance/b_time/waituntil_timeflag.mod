MODULE MainModule
  ! Tests: WaitUntil with \MaxTime and \TimeFlag: on timeout the flag becomes TRUE and execution
  ! continues; when the condition holds the flag is FALSE.
  PROC main()
    VAR bool late := FALSE;
    VAR num n := 1;
    WaitUntil n > 3 \MaxTime:=0.5 \TimeFlag:=late;
    TPWrite "timed out=" \Bool:=late;
    n := 4;
    WaitUntil n > 3 \MaxTime:=0.5 \TimeFlag:=late;
    TPWrite "timed out=" \Bool:=late;
  ENDPROC
ENDMODULE
