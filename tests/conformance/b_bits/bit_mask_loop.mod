MODULE MainModule
  ! Tests: BitCheck over all eight positions lists the set bits of 0b01010011 (= 83).
  PROC main()
    VAR byte data1 := 83;
    VAR string bits := "";
    FOR i FROM 8 TO 1 STEP -1 DO
      IF BitCheck(data1, i) THEN
        bits := bits + "1";
      ELSE
        bits := bits + "0";
      ENDIF
    ENDFOR
    TPWrite bits;
  ENDPROC
ENDMODULE
