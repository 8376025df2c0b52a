MODULE RuntimeDivReread
    ! The IF tests the input, and the division reads it AGAIN one step later.
    VAR num ratio := 0;

    PROC main()
        WHILE TRUE DO
            IF DInput(di_count) = 1 THEN
                ratio := 10 / DInput(di_count);
            ENDIF
        ENDWHILE
    ENDPROC
ENDMODULE
