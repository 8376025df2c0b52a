MODULE Wide
  ! more than 256 distinct values (the data segments' items outgrow one byte) and more
  ! than 256 frames (a local that counts: the state keys outgrow 8 bits of frame id)
  VAR num total := 0;
  PROC main()
    VAR num i := 0;
    WHILE i < 300 AND total < 1000 DO
      i := i + 1;
      total := total + 2;
    ENDWHILE
  ENDPROC
ENDMODULE
