MODULE MainModule
  ! Tests: Incr and Decr used as loop counters in a WHILE loop update the variable in place.
  PROC main()
    VAR num up := 0;
    VAR num down := 5;
    WHILE down > 0 DO
      Incr up;
      Decr down;
    ENDWHILE
    TPWrite "up=" \Num:=up;
    TPWrite "down=" \Num:=down;
  ENDPROC
ENDMODULE
