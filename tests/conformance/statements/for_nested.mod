MODULE for_nested
  ! Tests: nested FOR loops with different variables; the inner bound may
  ! depend on the outer variable.
  PROC main()
    VAR string line;
    FOR r FROM 1 TO 3 DO
      line := "";
      FOR c FROM 1 TO r DO
        line := line + "*";
      ENDFOR
      TPWrite line;
    ENDFOR
  ENDPROC
ENDMODULE
