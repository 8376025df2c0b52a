MODULE MainModule
  ! Tests: a menu loop with TPReadFK reads one answer per call until the exit key.
  PROC main()
    VAR num key := 0;
    VAR num rounds := 0;
    WHILE key <> 3 DO
      TPReadFK key, "Menu", "Run", "Count", "Exit", stEmpty, stEmpty;
      Incr rounds;
    ENDWHILE
    TPWrite "rounds=" \Num:=rounds;
  ENDPROC
ENDMODULE
