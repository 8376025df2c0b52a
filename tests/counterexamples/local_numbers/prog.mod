MODULE LocalNumbers
    ! A routine's own num data shows its numbers (0, 1), not the signal with that index.
    VAR num slots{2} := [1, 2];
    FUNC bool Check(INOUT num no, INOUT num side)
        no := GInput(giNo);
        side := 1;
        RETURN TRUE;
    ENDFUNC
    PROC Pick()
        VAR bool ok;
        VAR num side;
        VAR num no;
        ok := Check(no, side);
        slots{no} := side;
    ENDPROC
    PROC main()
        IF DInput(diGo) = 1 Pick;
    ENDPROC
ENDMODULE
