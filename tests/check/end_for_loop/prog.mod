MODULE EndForLoop
    ! A FOR loop adds 1, 2 and 3 to total, then main ends.
    VAR num total := 0;

    PROC main()
        FOR i FROM 1 TO 3 DO
            total := total + i;
        ENDFOR
    ENDPROC
ENDMODULE
