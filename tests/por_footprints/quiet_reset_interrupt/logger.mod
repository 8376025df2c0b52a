MODULE Logger
  ! a logger copying the server's tool under their mutex and formatting it to send
  PERS bool mutex := FALSE;
  PERS num toolX := 0;
  VAR num seen := 0;
  VAR string data := "";
  PROC main()
    FOR k FROM 1 TO 2 DO
      WHILE mutex DO  ! SHARED
      ENDWHILE
      mutex := TRUE;
      seen := toolX;  ! SHARED
      mutex := FALSE;
      data := "# " + NumToStr(seen, 1);  ! LOCAL
    ENDFOR
  ENDPROC
ENDMODULE
