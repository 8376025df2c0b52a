MODULE MainModule
  ! Tests: EXIT inside a WHILE loop ends the program in the iteration where it runs.
  PROC main()
    VAR num n := 0;
    WHILE TRUE DO
      Incr n;
      TPWrite "n=" \Num:=n;
      IF n = 3 EXIT;
    ENDWHILE
  ENDPROC
ENDMODULE
