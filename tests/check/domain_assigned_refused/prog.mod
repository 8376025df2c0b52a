MODULE DomainAssignedRefused
    ! The group input is compared at line 10 but also assigned at line 11:
    ! its value itself reaches recipe, so no finite default covers every
    ! behaviour and the checker still asks for --input-domain (RMC502).
    VAR signalgi gi_recipe;
    VAR num recipe := 0;

    PROC main()
        AliasIO "GI_RECIPE", gi_recipe;
        IF gi_recipe = 2 recipe := 1;
        recipe := GInput(gi_recipe);
    ENDPROC
ENDMODULE
