MODULE HandTrap
    ! Written for the test (issue 28, YuMi's hand driver copied into HOME and checked with no
    ! I/O configuration): the driver names every signal at run time ("hand_ready_" + side),
    ! so each AliasIO binds a stand-in input, one of them to a routine's own data. The
    ! interrupt watches hand_ready: the check keeps that AliasIO's stand-in in the states
    ! (model.alias_bindings), not the others, and the trap still runs.
    VAR intnum ready_int;
    VAR signaldi hand_ready;
    VAR signaldi hand_busy;
    VAR signalgo hand_cmd;
    VAR string side := "L";
    VAR num changes := 0;
    VAR num readies := 0;
    VAR num seen{2} := [0, 0];

    PROC main()
        VAR signaldi spare;
        VAR string io_name;
        io_name := "hand_ready_" + side;
        AliasIO io_name, hand_ready;
        AliasIO "hand_busy_" + side, hand_busy;
        AliasIO "hand_cmd_" + side, hand_cmd;
        AliasIO "hand_spare_" + side, spare;
        CONNECT ready_int WITH OnReady;
        ISignalDI \Single, hand_ready, 1, ready_int;
        WHILE readies < 2 DO
            IF hand_busy = 0 AND spare = 0 Incr readies;
            SetGO hand_cmd, readies;
        ENDWHILE
        ! a trap that ran twice would index past the array: \Single forbids it
        seen{changes + 1} := 1;
    ENDPROC

    TRAP OnReady
        changes := changes + 1;
    ENDTRAP
ENDMODULE
