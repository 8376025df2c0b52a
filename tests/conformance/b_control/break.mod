MODULE MainModule
  ! Tests: Break stops program execution immediately; in a run it ends like Stop (exit code 0).
  ! ASSUMPTION: a run treats Break like Stop (the brief's exit-code table lists Stop and EXIT).
  PROC main()
    VAR num n := 0;
    WHILE n < 10 DO
      Incr n;
      IF n = 2 Break;
      TPWrite "n=" \Num:=n;
    ENDWHILE
    TPWrite "not reached";
  ENDPROC
ENDMODULE
