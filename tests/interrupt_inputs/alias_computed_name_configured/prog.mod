MODULE AliasComputedTrap
    ! Written for the test (issue 28): the interrupt is ordered on signal data that an AliasIO
    ! binds to a name computed at run time ("di" + which). With the I/O configuration loaded
    ! the check keeps every digital input of EIO.cfg in the states, any of which the name
    ! may give (model.alias_bindings), but not the group input giCode, which the program
    ! reads where it reads it; the verdicts are those of keeping every input.
    VAR intnum reset_int;
    VAR signaldi alias_diReset;
    VAR string which := "Reset";
    VAR num slot := 1;
    VAR bool was_reset := FALSE;
    VAR num bins{3} := [0, 0, 0];

    PROC main()
        AliasIO "di" + which, alias_diReset;
        CONNECT reset_int WITH OnReset;
        ISignalDI alias_diReset, 1, reset_int;
        WHILE TRUE DO
            WaitDI diStart, 1;
            IF DInput(diPart) = 1 AND GInput(giCode) = 2 THEN
                slot := slot + 1;
                bins{slot} := 1;
            ENDIF
        ENDWHILE
    ENDPROC

    TRAP OnReset
        was_reset := TRUE;
        slot := 1;
        bins := [0, 0, 0];
    ENDTRAP
ENDMODULE
