MODULE VmTestDispatch
    ! TEST on a num counter, on a digital input (read once by TEST), on a sum
    ! of two inputs and on a string; several values per CASE, DEFAULT or none.
    VAR signaldi mode;
    VAR num n := 0;
    VAR num kind := -1;
    VAR num level := -1;
    VAR num sum := -1;
    VAR num hits := 0;
    VAR num first := 0;
    VAR string name := "a";
    VAR num letter := 0;
    CONST num TWO := 2;

    PROC main()
        AliasIO "DI_MODE", mode;
        WHILE TRUE DO
            n := (n + 1) MOD 6;
            TEST n
            CASE 0, 2, 4:
                kind := 0;
            CASE 1, TWO + 1:
                kind := 1;
            CASE 1, 5:
                kind := 5;
            DEFAULT:
                kind := 9;
            ENDTEST
            TEST mode
            CASE 1:
                level := 1;
            DEFAULT:
                level := 0;
            ENDTEST
            TEST DInput(di_x) + DInput(di_y)
            CASE 0:
                sum := 0;
            CASE 2:
                sum := 2;
            ENDTEST
            TEST kind
            CASE 9:
                first := 9;
            ENDTEST
            TEST name
            CASE "b", "c":
                letter := 2;
                name := "a";
            CASE "a":
                letter := 1;
                name := "b";
            ENDTEST
        ENDWHILE
    ENDPROC
ENDMODULE
