MODULE VmPropertyAtoms
    ! A request counter x (0, 1, 2, then back to 0) with a busy output, and a
    ! divisor d = 2 - x that is 0 when x = 2: atoms divide by it.
    VAR signaldo busy;
    VAR num x := 0;
    VAR num d := 2;
    VAR num served := 0;

    PROC main()
        AliasIO "DO_BUSY", busy;
        WHILE TRUE DO
            IF DInput(di_req) = 1 THEN
                SetDO busy, 1;
                x := x + 1;
                IF x >= 3 x := 0;
                served := 1;
                SetDO busy, 0;
            ENDIF
            d := 2 - x;
        ENDWHILE
    ENDPROC
ENDMODULE
