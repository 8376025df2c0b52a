MODULE PartLib
    ! A library a main program calls (no main of its own): FUNCs and a procedure with
    ! parameters. Checked routine by routine (check --entry all, the default here).
    PERS num nCount := 0;

    ! a defect: a width of 0 divides by zero (0 is among the values tried)
    FUNC num Ratio(num width, num height)
        IF height > 100 THEN
            RETURN 1;
        ENDIF
        RETURN height / width;
    ENDFUNC

    ! safe: the code guards the index, so every value tried ends well
    FUNC num Slot(num code)
        VAR num slots{3} := [10, 20, 30];
        IF code < 1 OR code > 3 RETURN 0;
        RETURN slots{code};
    ENDFUNC

    ! a bool and a string: both bool values; the string keeps its neutral value ""
    PROC Label(bool large, string name)
        IF large THEN
            nCount := nCount + 2;
        ELSE
            nCount := nCount + 1;
        ENDIF
    ENDPROC

    ! no parameters: called as it is
    FUNC bool Ready()
        RETURN nCount > 0;
    ENDFUNC

    ! not checked: a PERS parameter no driver can pass
    PROC Reset(PERS num counter)
        counter := 0;
    ENDPROC
ENDMODULE
