#pragma once
// The unit tests' deck: a small valid Problem list (a 2 x 1 rectangle of 2 x 1 Q4 Enhanced elements,
// nodes at x = 0, 1, 2 and y = 0, 1, Neo-Hookean, left held in x, its reaction written). Tests break one
// thing at a time or add what they test.
#include <Teuchos_XMLParameterListHelpers.hpp>

namespace contessa::deck::test {

inline Teuchos::RCP<Teuchos::ParameterList> goodProblem() {
  return Teuchos::getParametersFromXmlString(R"XML(
<ParameterList name="Problem">
  <ParameterList name="Mesh">
    <Parameter name="Type" type="string" value="Rectangle"/>
    <Parameter name="Length X" type="double" value="2.0"/>
    <Parameter name="Elements X" type="int" value="2"/>
  </ParameterList>
  <ParameterList name="Blocks">
    <ParameterList name="block_1">
      <Parameter name="Element" type="string" value="Q4 Enhanced"/>
      <Parameter name="Material" type="string" value="steel"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Materials">
    <ParameterList name="steel">
      <Parameter name="Model" type="string" value="Neo-Hookean"/>
      <Parameter name="Young's Modulus" type="double" value="200.0"/>
      <Parameter name="Poisson's Ratio" type="double" value="0.3"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Dirichlet Conditions">
    <ParameterList name="fix">
      <Parameter name="Node Set" type="string" value="left"/>
      <Parameter name="Component" type="string" value="x"/>
    </ParameterList>
  </ParameterList>
  <ParameterList name="Output">
    <Parameter name="Reaction Node Sets" type="Array(string)" value="{left}"/>
  </ParameterList>
</ParameterList>)XML");
}

}  // namespace contessa::deck::test
