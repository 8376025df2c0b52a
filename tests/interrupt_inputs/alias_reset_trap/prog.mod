MODULE AliasResetTrap
    ! Written for the test (issue 28, a palletizing cell's PickMaster server task): the
    ! interrupt is ordered on signal data that an AliasIO binds to diReset, named by a
    ! string variable assigned just before. The check keeps diReset alone in the states
    ! (model.alias_bindings), not every input, and the trap still runs.
    VAR intnum reset_int;
    VAR signaldi alias_diReset;
    VAR num slot := 1;
    VAR bool was_reset := FALSE;
    VAR num bins{3} := [0, 0, 0];

    PROC main()
        VAR string signalName;
        signalName := "diReset";
        AliasIO signalName, alias_diReset;
        CONNECT reset_int WITH OnReset;
        ISignalDI alias_diReset, 1, reset_int;
        WHILE TRUE DO
            WaitDI diStart, 1;
            IF DInput(diPart) = 1 THEN
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
