MODULE DeadDataForLoopInCallee
    ! A command from a free input is split into its digits by a routine with two FOR
    ! loops over its own data (as socket_split_fields' strSplit).  'ok' is written after
    ! each split and read after that, so it is dead at the call and while the routine
    ! runs: main waits at the call.  The first round starts with ok FALSE, the later ones
    ! with ok TRUE; the stored states forget it, the counterexamples must still replay.
    VAR signaldi diCmd;
    VAR num digits{3};
    VAR num count := 0;
    VAR num command := 0;
    VAR bool ok := FALSE;
    VAR num action := 0;

    PROC main()
        AliasIO "DI_CMD", diCmd;
        WHILE TRUE DO
            command := 12 + 9 * diCmd;
            split command, digits, count;
            ok := count = 2;
            IF ok AND digits{1} = 2 action := 1;
            IF ok AND digits{1} = 1 action := 2;
        ENDWHILE
    ENDPROC

    PROC split(num value, VAR num result{*}, VAR num n)
        VAR num rest := 0;
        VAR num digit := 0;
        FOR i FROM 1 TO Dim(result, 1) DO
            result{i} := 0;
        ENDFOR
        n := 0;
        rest := value;
        FOR i FROM 1 TO Dim(result, 1) DO
            digit := rest MOD 10;
            result{i} := digit;
            n := n + 1;
            rest := rest DIV 10;
            IF rest = 0 RETURN;
        ENDFOR
    ENDPROC
ENDMODULE
